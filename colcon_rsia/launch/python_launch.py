# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""ROS 2 Python launch files, read with the stdlib ``ast`` (never run).

A small interpreter walks ``generate_launch_description()`` (and the module
functions it calls) over a subset of Python: assignments, lists, dicts,
tuples, f-strings, arithmetic on known values, ``if`` on known values,
``for`` over known sequences, and the launch / launch_ros API, which builds
the actions of :mod:`colcon_rsia.launch.ir`. Module-level code other than
imports, constants and definitions is never interpreted. Calls to anything
else give an unknown value with a note; an ``if`` whose condition is not
known runs both branches and marks what they create; a loop over an unknown
sequence runs its body once and marks what it creates.
"""

import ast
import builtins
import os
import re
import string

from colcon_rsia.launch import safe_eval
from colcon_rsia.launch.common import location
from colcon_rsia.launch.ir import Action
from colcon_rsia.launch.ir import Group
from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.model import LaunchError
from colcon_rsia.launch.notes import shorten
from colcon_rsia.launch.python_launch_api import ArgError
from colcon_rsia.launch.python_launch_api import Args
from colcon_rsia.launch.python_launch_api import LAUNCH_API
from colcon_rsia.launch.python_launch_values import Bound
from colcon_rsia.launch.python_launch_values import BranchEnd
from colcon_rsia.launch.python_launch_values import BreakSignal
from colcon_rsia.launch.python_launch_values import BudgetExceeded
from colcon_rsia.launch.python_launch_values import ContinueSignal
from colcon_rsia.launch.python_launch_values import Frame
from colcon_rsia.launch.python_launch_values import Function
from colcon_rsia.launch.python_launch_values import HashableValue
from colcon_rsia.launch.python_launch_values import LAUNCH_MODULES
from colcon_rsia.launch.python_launch_values import LaunchDescription
from colcon_rsia.launch.python_launch_values import MAX_CALL_DEPTH
from colcon_rsia.launch.python_launch_values import MAX_CODE_NESTING
from colcon_rsia.launch.python_launch_values import MAX_LOOP
from colcon_rsia.launch.python_launch_values import MAX_SIZE
from colcon_rsia.launch.python_launch_values import MAX_STEPS
from colcon_rsia.launch.python_launch_values import MAX_TOTAL_STEPS
from colcon_rsia.launch.python_launch_values import MISSING
from colcon_rsia.launch.python_launch_values import Ref
from colcon_rsia.launch.python_launch_values import ReturnSignal
from colcon_rsia.launch.python_launch_values import SCALARS
from colcon_rsia.launch.safe_eval import Unresolved


def read_python_launch(path, text, loader, root=None):
    """The ROS 2 actions of a Python launch file.

    :param root: not used (an XML reader's argument; every reader takes
      the same)
    :raises LaunchError: when the file is not valid Python
    """
    try:
        tree = ast.parse(text, filename=path)
    except SyntaxError as e:
        raise LaunchError(f'{path}: not valid Python (line {e.lineno}: '
                          f'{e.msg}).')
    except (ValueError, RecursionError, MemoryError) as e:
        raise LaunchError(f'{path}: cannot be parsed as Python '
                          f'({type(e).__name__}).')
    interpreter = _Interpreter(path, loader)
    return interpreter.launch_description(tree)


class _Interpreter:

    def __init__(self, path, loader):
        self.path = path
        self.loader = loader
        self.globals = {'__file__': os.path.abspath(path),
                        '__name__': '__launch__'}
        self.frames = []
        self.uncertain = []  # notes of the unknown branches we are in
        self.steps = 0
        self.nesting = 0

    # helpers

    def loc(self, node):
        return location(self.path, getattr(node, 'lineno', 0))

    def note(self, node, text):
        self.loader.note(f'{self.loc(node)}: {text}')

    def unknown(self, node, text):
        """An unknown value, noted once at file level."""
        self.note(node, text)
        return UnknownValue(f'{self.loc(node)}: {text}')

    def step(self):
        self.steps += 1
        self.loader.python_steps += 1
        if self.steps > MAX_STEPS or \
                self.loader.python_steps > MAX_TOTAL_STEPS:
            raise BudgetExceeded()

    # the module

    def launch_description(self, tree):
        try:
            self.module(tree)
            function = self.globals.get('generate_launch_description')
            if not isinstance(function, Function):
                self.loader.note(f'{self.path}: no generate_launch_'
                                 'description() function; nothing launched')
                return []
            node = function.node
            value = self.call_function(function, [], {}, node)
        except BudgetExceeded:
            self.loader.note(f'{self.path}: the launch file takes too many '
                             'steps to interpret; the rest is not read')
            return []
        if isinstance(value, LaunchDescription):
            return value.entities
        if isinstance(value, UnknownValue):
            self.loader.note(f'{self.path}: generate_launch_description() '
                             f'does not give a known launch description '
                             f'({value.reason})')
        else:
            self.loader.note(f'{self.path}: generate_launch_description() '
                             'does not return a LaunchDescription')
        return []

    def module(self, tree):
        for stmt in tree.body:
            if isinstance(stmt, (ast.Import, ast.ImportFrom)):
                self.import_(stmt, self.globals)
            elif isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef)):
                self.define(stmt, self.globals, [self.globals])
            elif isinstance(stmt, (ast.Assign, ast.AnnAssign)):
                self.frames.append(Frame(self.globals, [], 0))
                try:
                    self.statement(stmt, self.globals)
                finally:
                    self.frames.pop()
            elif isinstance(stmt, ast.Expr) and isinstance(
                    stmt.value, ast.Constant):
                continue  # a docstring
            elif isinstance(stmt, ast.If) and _is_main_guard(stmt.test):
                continue  # never runs under launch
            elif isinstance(stmt, ast.Try):
                for inner in stmt.body:
                    if isinstance(inner, (ast.Import, ast.ImportFrom)):
                        self.import_(inner, self.globals)
                    else:
                        self.note(inner, 'module-level statement in try: '
                                  'not interpreted')
            else:
                self.note(stmt, f'module-level {type(stmt).__name__} '
                          'statement not interpreted')

    def import_(self, stmt, env):
        if isinstance(stmt, ast.Import):
            for alias in stmt.names:
                if alias.asname:
                    env[alias.asname] = Ref(alias.name)
                else:
                    top = alias.name.split('.')[0]
                    env[top] = Ref(top)
            return
        module = '.' * stmt.level + (stmt.module or '')
        for alias in stmt.names:
            if alias.name == '*':
                self.note(stmt, f'from {module} import * not followed')
                continue
            env[alias.asname or alias.name] = Ref(f'{module}.{alias.name}')

    def define(self, stmt, env, closure):
        args = stmt.args
        defaults = [self.eval(d, env) for d in args.defaults]
        kw_defaults = {}
        for arg, default in zip(args.kwonlyargs, args.kw_defaults):
            if default is not None:
                kw_defaults[arg.arg] = self.eval(default, env)
        env[stmt.name] = Function(stmt, defaults, kw_defaults,
                                  list(closure), stmt.name)

    # calls of module functions

    def call_function(self, function, args, kwargs, call_node):
        if len(self.frames) >= MAX_CALL_DEPTH:
            return self.unknown(call_node, f'calls nested deeper than '
                                f'{MAX_CALL_DEPTH} (recursion?)')
        node = function.node
        env = {}
        try:
            self.bind(function, args, kwargs, env)
        except TypeError as e:
            return self.unknown(call_node, f'call of {function.name}() not '
                                f'understood ({e})')
        frame = Frame(env, [], len(self.uncertain))
        self.frames.append(frame)
        closure = function.closure
        try:
            if isinstance(node, ast.Lambda):
                return self.eval(node.body, env, closure)
            value = None
            try:
                self.block(node.body, env, closure)
            except ReturnSignal as r:
                value = r.value
            except (BreakSignal, ContinueSignal, BranchEnd):
                pass
            if frame.conditional_returns:
                value = self.merge_returns(frame.conditional_returns, value,
                                           call_node)
            return value
        finally:
            self.frames.pop()

    def bind(self, function, args, kwargs, env):
        spec = function.node.args
        positional = [a.arg for a in spec.posonlyargs + spec.args]
        defaults = dict(zip(positional[len(positional) -
                                       len(function.defaults):],
                            function.defaults))
        args = list(args)
        for name in positional:
            if args:
                env[name] = args.pop(0)
            elif name in kwargs:
                env[name] = kwargs.pop(name)
            elif name in defaults:
                env[name] = defaults[name]
            else:
                raise TypeError(f'missing argument {name}')
        if spec.vararg:
            env[spec.vararg.arg] = list(args)
        elif args:
            raise TypeError('too many arguments')
        for arg in spec.kwonlyargs:
            if arg.arg in kwargs:
                env[arg.arg] = kwargs.pop(arg.arg)
            elif arg.arg in function.kw_defaults:
                env[arg.arg] = function.kw_defaults[arg.arg]
            else:
                raise TypeError(f'missing argument {arg.arg}')
        if spec.kwarg:
            env[spec.kwarg.arg] = dict(kwargs)
        elif kwargs:
            raise TypeError(f'unexpected argument {next(iter(kwargs))}')

    def merge_returns(self, conditional, final, node):
        values = [v for v, _ in conditional] + [final]
        if not all(isinstance(v, LaunchDescription) for v in values):
            return self.unknown(node, 'the function returns different '
                                'values depending on conditions not known '
                                'statically')
        entities = []
        notes = []
        for value, note in conditional:
            entities.append(Group(actions=value.entities, scoped=False,
                                  notes=[note], location=self.loc(node)))
            notes.append(note)
        entities.append(Group(
            actions=final.entities, scoped=False, location=self.loc(node),
            notes=[f'{self.loc(node)}: returned only when an earlier return '
                   f'does not happen ({"; ".join(notes)})']))
        return LaunchDescription(entities)

    # statements

    def block(self, body, env, closure=None):
        for stmt in body:
            self.statement(stmt, env, closure)

    def statement(self, stmt, env, closure=None):
        self.step()
        kind = type(stmt).__name__
        method = getattr(self, 'stmt_' + kind, None)
        if method is None:
            self.note(stmt, f'{kind} statement not interpreted')
            return
        if self.nesting >= MAX_CODE_NESTING:
            self.note(stmt, 'code nested too deeply to interpret')
            return
        self.nesting += 1
        try:
            method(stmt, env, closure)
        finally:
            self.nesting -= 1

    def stmt_Expr(self, stmt, env, closure):  # noqa: N802
        self.eval(stmt.value, env, closure)

    def stmt_Pass(self, stmt, env, closure):  # noqa: N802
        pass

    def stmt_Import(self, stmt, env, closure):  # noqa: N802
        self.import_(stmt, env)

    stmt_ImportFrom = stmt_Import  # noqa: N815

    def stmt_FunctionDef(self, stmt, env, closure):  # noqa: N802
        self.define(stmt, env, [env] + list(closure or [self.globals]))

    def stmt_Return(self, stmt, env, closure):  # noqa: N802
        value = None if stmt.value is None else self.eval(stmt.value, env,
                                                          closure)
        frame = self.frames[-1] if self.frames else None
        if frame is not None and len(self.uncertain) > frame.base:
            frame.conditional_returns.append((value, self.uncertain[-1]))
            raise BranchEnd()  # ends this branch only
        raise ReturnSignal(value)

    def stmt_Break(self, stmt, env, closure):  # noqa: N802
        raise BreakSignal()

    def stmt_Continue(self, stmt, env, closure):  # noqa: N802
        raise ContinueSignal()

    def stmt_Assign(self, stmt, env, closure):  # noqa: N802
        value = self.eval(stmt.value, env, closure)
        for target in stmt.targets:
            self.assign(target, value, env, closure)

    def stmt_AnnAssign(self, stmt, env, closure):  # noqa: N802
        if stmt.value is not None:
            self.assign(stmt.target, self.eval(stmt.value, env, closure),
                        env, closure)

    def stmt_AugAssign(self, stmt, env, closure):  # noqa: N802
        current = self.eval(stmt.target, env, closure)
        value = self.eval(stmt.value, env, closure)
        if isinstance(current, list) and isinstance(stmt.op, ast.Add):
            if isinstance(value, (list, tuple)):
                self._grow(current, value, stmt)
                return
        result = self.binary(stmt.op, current, value, stmt)
        self.assign(stmt.target, result, env, closure)

    def stmt_If(self, stmt, env, closure):  # noqa: N802
        test = self.truth(self.eval(stmt.test, env, closure))
        if test is True:
            self.block(stmt.body, env, closure)
        elif test is False:
            self.block(stmt.orelse, env, closure)
        else:
            text = shorten(_source(stmt.test), 50)
            self.note(stmt, f'condition "{text}" not known statically; both '
                      'branches are read and what they start is marked')
            self.branches(
                env, closure,
                [(stmt.body, f'{self.loc(stmt)}: only when "{text}" '
                  'is true, which is not known statically'),
                 (stmt.orelse, f'{self.loc(stmt)}: only when "{text}" '
                  'is false, which is not known statically')])

    def branches(self, env, closure, alternatives):
        """Run alternative blocks from the same state; merge what differs."""
        before = dict(env)
        results = []
        for body, note in alternatives:
            env.clear()
            env.update(before)
            self.uncertain.append(note)
            try:
                self.block(body, env, closure)
            except (BreakSignal, ContinueSignal, BranchEnd):
                pass
            finally:
                self.uncertain.pop()
            results.append(dict(env))
        env.clear()
        names = set(before)
        for result in results:
            names.update(result)
        notes = [note for _, note in alternatives]
        for name in names:
            values = [r.get(name, before.get(name, MISSING))
                      for r in results]
            first = values[0]
            if all(_same(first, v) for v in values[1:]):
                if first is not MISSING:
                    env[name] = first
            else:
                env[name] = _alternatives(name, values, notes)

    def stmt_For(self, stmt, env, closure):  # noqa: N802
        iterable = self.eval(stmt.iter, env, closure)
        items = self.sequence(iterable)
        if items is None:
            text = shorten(_source(stmt.iter), 50)
            note = (f'{self.loc(stmt)}: created in a loop over "{text}", '
                    'which is not known statically (listed once)')
            self.note(stmt, f'loop over "{text}" not known statically; its '
                      'body is read once and what it starts is marked')
            self.assign(stmt.target, UnknownValue(note), env, closure)
            self.branches(env, closure, [(stmt.body, note), ([], note)])
            return
        for item in items:
            self.step()
            self.assign(stmt.target, item, env, closure)
            try:
                self.block(stmt.body, env, closure)
            except ContinueSignal:
                continue
            except BreakSignal:
                return
        self.block(stmt.orelse, env, closure)

    def stmt_While(self, stmt, env, closure):  # noqa: N802
        test = self.truth(self.eval(stmt.test, env, closure))
        if test is False:
            self.block(stmt.orelse, env, closure)
            return
        note = (f'{self.loc(stmt)}: created in a while loop (listed once, '
                'it may run any number of times)')
        self.note(stmt, 'while loop read once; what it starts is marked')
        self.branches(env, closure, [(stmt.body, note), ([], note)])

    def stmt_With(self, stmt, env, closure):  # noqa: N802
        for item in stmt.items:
            self.eval(item.context_expr, env, closure)
            if item.optional_vars is not None:
                self.assign(item.optional_vars,
                            self.unknown(stmt, 'value of a with statement'),
                            env, closure)
        self.block(stmt.body, env, closure)

    def stmt_Try(self, stmt, env, closure):  # noqa: N802
        self.block(stmt.body, env, closure)
        self.block(stmt.orelse, env, closure)
        self.block(stmt.finalbody, env, closure)

    def stmt_Assert(self, stmt, env, closure):  # noqa: N802
        pass

    def stmt_Raise(self, stmt, env, closure):  # noqa: N802
        self.note(stmt, 'raise not interpreted')

    def stmt_Global(self, stmt, env, closure):  # noqa: N802
        pass

    stmt_Nonlocal = stmt_Global  # noqa: N815

    def stmt_Delete(self, stmt, env, closure):  # noqa: N802
        for target in stmt.targets:
            if isinstance(target, ast.Name):
                env.pop(target.id, None)

    # assignment

    def assign(self, target, value, env, closure):
        if isinstance(target, ast.Name):
            env[target.id] = value
        elif isinstance(target, (ast.Tuple, ast.List)):
            items = self.sequence(value)
            names = target.elts
            if items is None or len(items) != len(names) or any(
                    isinstance(n, ast.Starred) for n in names):
                for name in names:
                    inner = name.value if isinstance(name, ast.Starred) \
                        else name
                    self.assign(inner, UnknownValue(
                        f'{self.loc(target)}: unpacking of a value not '
                        'known statically'), env, closure)
                return
            for name, item in zip(names, items):
                self.assign(name, item, env, closure)
        elif isinstance(target, ast.Subscript):
            container = self.eval(target.value, env, closure)
            key = self.eval(target.slice, env, closure)
            if isinstance(container, dict) and _hashable(key):
                container[key] = value
            elif isinstance(container, list) and isinstance(key, int) and \
                    -len(container) <= key < len(container):
                container[key] = value
            else:
                self.note(target, 'assignment to an item not interpreted')
        else:
            self.note(target, f'assignment to {type(target).__name__} not '
                      'interpreted')

    # expressions

    def lookup(self, name, env, closure):
        if name in env:
            return env[name]
        for scope in closure or ():
            if name in scope:
                return scope[name]
        if name in self.globals:
            return self.globals[name]
        if name in _PYTHON_BUILTINS:
            return Ref('builtins.' + name)  # few are interpreted
        return MISSING

    def eval(self, node, env, closure=None, depth=0):
        self.step()
        if self.nesting >= MAX_CODE_NESTING:
            return self.unknown(node, 'code nested too deeply to interpret')
        method = getattr(self, 'ex_' + type(node).__name__, None)
        if method is None:
            return self.unknown(
                node, f'{type(node).__name__} expression not interpreted')
        self.nesting += 1
        try:
            return method(node, env, closure, depth + 1)
        finally:
            self.nesting -= 1

    def ex_Constant(self, node, env, closure, depth):  # noqa: N802
        if isinstance(node.value, SCALARS):
            return node.value
        return UnknownValue(f'{self.loc(node)}: constant of type '
                            f'{type(node.value).__name__}')

    def ex_Name(self, node, env, closure, depth):  # noqa: N802
        value = self.lookup(node.id, env, closure)
        if value is MISSING:
            return self.unknown(node, f"name '{node.id}' is not defined in "
                                'the launch file')
        return value

    def ex_Attribute(self, node, env, closure, depth):  # noqa: N802
        obj = self.eval(node.value, env, closure, depth)
        if isinstance(obj, Ref):
            return Ref(f'{obj.qualname}.{node.attr}')
        if isinstance(obj, UnknownValue):
            return obj
        if node.attr.startswith('_'):
            return self.unknown(node, f'attribute {node.attr} not '
                                'interpreted')
        return Bound(obj, node.attr)

    def ex_Call(self, node, env, closure, depth):  # noqa: N802
        func = self.eval(node.func, env, closure, depth)
        args = []
        for a in node.args:
            if isinstance(a, ast.Starred):
                value = self.eval(a.value, env, closure, depth)
                items = self.sequence(value)
                if items is None:
                    return self.unknown(node, 'call with *arguments not '
                                        'known statically')
                args.extend(items)
            else:
                args.append(self.eval(a, env, closure, depth))
        kwargs = {}
        for k in node.keywords:
            value = self.eval(k.value, env, closure, depth)
            if k.arg is None:
                if not isinstance(value, dict):
                    return self.unknown(node, 'call with **arguments not '
                                        'known statically')
                kwargs.update({str(key): v for key, v in value.items()})
            else:
                kwargs[k.arg] = value
        return self.call(func, args, kwargs, node)

    def ex_BinOp(self, node, env, closure, depth):  # noqa: N802
        left = self.eval(node.left, env, closure, depth)
        right = self.eval(node.right, env, closure, depth)
        return self.binary(node.op, left, right, node)

    def ex_UnaryOp(self, node, env, closure, depth):  # noqa: N802
        value = self.eval(node.operand, env, closure, depth)
        if isinstance(node.op, ast.Not):
            truth = self.truth(value)
            if truth is None:
                return UnknownValue(f'{self.loc(node)}: not of a value not '
                                    'known statically')
            return not truth
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            if isinstance(node.op, ast.USub):
                return -value
            if isinstance(node.op, ast.UAdd):
                return value
        return UnknownValue(f'{self.loc(node)}: operator not interpreted')

    def ex_BoolOp(self, node, env, closure, depth):  # noqa: N802
        value = None
        for operand in node.values:
            value = self.eval(operand, env, closure, depth)
            truth = self.truth(value)
            if truth is None:
                return UnknownValue(f'{self.loc(node)}: '
                                    f'"{shorten(_source(node), 50)}" is not '
                                    'known statically')
            if isinstance(node.op, ast.And) and not truth:
                return value
            if isinstance(node.op, ast.Or) and truth:
                return value
        return value

    def ex_Compare(self, node, env, closure, depth):  # noqa: N802
        left = self.eval(node.left, env, closure, depth)
        for op, right_node in zip(node.ops, node.comparators):
            right = self.eval(right_node, env, closure, depth)
            result = _compare(op, left, right)
            if result is None:
                return UnknownValue(
                    f'{self.loc(node)}: comparison '
                    f'"{shorten(_source(node), 50)}" not known statically')
            if not result:
                return False
            left = right
        return True

    def ex_IfExp(self, node, env, closure, depth):  # noqa: N802
        truth = self.truth(self.eval(node.test, env, closure, depth))
        if truth is True:
            return self.eval(node.body, env, closure, depth)
        if truth is False:
            return self.eval(node.orelse, env, closure, depth)
        text = shorten(_source(node.test), 50)
        notes = [f'{self.loc(node)}: only when "{text}" is true, which is '
                 'not known statically',
                 f'{self.loc(node)}: only when "{text}" is false, which is '
                 'not known statically']
        values = []
        for branch, note in zip((node.body, node.orelse), notes):
            self.uncertain.append(note)
            try:
                values.append(self.eval(branch, env, closure, depth))
            finally:
                self.uncertain.pop()
        if _same(values[0], values[1]):
            return values[0]
        if all(isinstance(v, Action) or v is None for v in values):
            self.note(node, f'condition "{text}" not known statically; both '
                      'alternatives are read and marked')
            return Group(actions=[
                Group(actions=[v], scoped=False, notes=[note])
                for v, note in zip(values, notes) if v is not None],
                scoped=False, location=self.loc(node))
        return self.unknown(node, f'value depends on "{text}", which is not '
                            'known statically')

    def ex_JoinedStr(self, node, env, closure, depth):  # noqa: N802
        parts = []
        for value in node.values:
            if isinstance(value, ast.Constant):
                parts.append(str(value.value))
                continue
            item = self.eval(value.value, env, closure, depth)
            if not isinstance(item, SCALARS):
                return self.unknown(node, 'f-string of a value not known '
                                    'before launch (use a list of '
                                    'substitutions)')
            spec = ''
            if value.format_spec is not None:
                spec = self.eval(value.format_spec, env, closure, depth)
                if not isinstance(spec, str) or not _safe_spec(spec):
                    return self.unknown(node, 'format spec not interpreted')
            if value.conversion == ord('r'):
                item = repr(item)
            try:
                parts.append(format(item, spec))
            except (ValueError, TypeError):
                return self.unknown(node, 'f-string format not understood')
        return self.limit(''.join(parts), node)

    def ex_FormattedValue(self, node, env, closure, depth):  # noqa: N802
        return self.ex_JoinedStr(ast.JoinedStr(values=[node]), env, closure,
                                 depth)

    def ex_List(self, node, env, closure, depth):  # noqa: N802
        out = []
        for elt in node.elts:
            if isinstance(elt, ast.Starred):
                items = self.sequence(self.eval(elt.value, env, closure,
                                                depth))
                if items is None:
                    out.append(self.unknown(elt, 'unpacking of a value not '
                                            'known statically'))
                else:
                    self._grow(out, items, node)
            else:
                out.append(self.eval(elt, env, closure, depth))
        return out

    def ex_Tuple(self, node, env, closure, depth):  # noqa: N802
        return tuple(self.ex_List(node, env, closure, depth))

    def ex_Set(self, node, env, closure, depth):  # noqa: N802
        return self.ex_List(node, env, closure, depth)

    def ex_Dict(self, node, env, closure, depth):  # noqa: N802
        out = {}
        for key, value in zip(node.keys, node.values):
            item = self.eval(value, env, closure, depth)
            if key is None:
                if isinstance(item, dict):
                    out.update(item)
                else:
                    out[f'<unknown {len(out)}>'] = self.unknown(
                        node, 'dictionary unpacking not known statically')
                continue
            k = self.eval(key, env, closure, depth)
            if not _hashable(k):
                k = HashableValue(k)
            out[k] = item
        return out

    def ex_Subscript(self, node, env, closure, depth):  # noqa: N802
        container = self.eval(node.value, env, closure, depth)
        key = self.eval(node.slice, env, closure, depth)
        if isinstance(container, Ref) and container.qualname == \
                'os.environ':
            return self.environ(key, None, node, required=True)
        if isinstance(container, (list, tuple, str, dict)) and (
                _hashable(key) or isinstance(key, slice)):
            try:
                return container[key]
            except (KeyError, IndexError, TypeError):
                pass
        return self.unknown(node, f'"{shorten(_source(node), 50)}" not '
                            'known statically')

    def ex_Slice(self, node, env, closure, depth):  # noqa: N802
        parts = [None if p is None else self.eval(p, env, closure, depth)
                 for p in (node.lower, node.upper, node.step)]
        if all(p is None or isinstance(p, int) for p in parts):
            return slice(*parts)
        return UnknownValue(f'{self.loc(node)}: slice not known')

    def ex_Lambda(self, node, env, closure, depth):  # noqa: N802
        defaults = [self.eval(d, env, closure, depth)
                    for d in node.args.defaults]
        return Function(node, defaults, {}, [env] + list(closure or []),
                        'lambda')

    def ex_NamedExpr(self, node, env, closure, depth):  # noqa: N802
        value = self.eval(node.value, env, closure, depth)
        self.assign(node.target, value, env, closure)
        return value

    def ex_ListComp(self, node, env, closure, depth):  # noqa: N802
        out = []
        self.comprehension(node, node.generators, 0, dict(env), closure,
                           depth, lambda e: out.append(
                               self.eval(node.elt, e, closure, depth)))
        return out

    ex_SetComp = ex_ListComp  # noqa: N815
    ex_GeneratorExp = ex_ListComp  # noqa: N815

    def ex_DictComp(self, node, env, closure, depth):  # noqa: N802
        out = {}

        def add(e):
            key = self.eval(node.key, e, closure, depth)
            out[key if _hashable(key) else HashableValue(key)] = self.eval(
                node.value, e, closure, depth)
        self.comprehension(node, node.generators, 0, dict(env), closure,
                           depth, add)
        return out

    def comprehension(self, node, generators, index, env, closure, depth,
                      emit):
        if index == len(generators):
            emit(env)
            return
        generator = generators[index]
        items = self.sequence(self.eval(generator.iter, env, closure, depth))
        if items is None:
            note = (f'{self.loc(node)}: created in a comprehension over a '
                    'value not known statically (listed once)')
            self.note(node, 'comprehension over a value not known '
                      'statically; its element is read once and marked')
            self.uncertain.append(note)
            try:
                self.assign(generator.target, UnknownValue(note), env,
                            closure)
                self.comprehension(node, generators, index + 1, env,
                                   closure, depth, emit)
            finally:
                self.uncertain.pop()
            return
        for item in items:
            self.step()
            self.assign(generator.target, item, env, closure)
            keep = True
            for condition in generator.ifs:
                truth = self.truth(self.eval(condition, env, closure, depth))
                if truth is None:
                    note = (f'{self.loc(node)}: only when '
                            f'"{shorten(_source(condition), 50)}", which is '
                            'not known statically')
                    self.uncertain.append(note)
                    try:
                        self.comprehension(node, generators, index + 1, env,
                                           closure, depth, emit)
                    finally:
                        self.uncertain.pop()
                    keep = False
                    break
                if not truth:
                    keep = False
                    break
            if keep:
                self.comprehension(node, generators, index + 1, env, closure,
                                   depth, emit)

    # value helpers

    def limit(self, value, node):
        if isinstance(value, (str, list, tuple)) and len(value) > MAX_SIZE:
            return self.unknown(node, 'value too large')
        if isinstance(value, int) and value.bit_length() > 4000:
            return self.unknown(node, 'number too large')
        return value

    def _grow(self, target, items, node):
        if len(target) + len(items) > MAX_SIZE:
            target.append(self.unknown(node, 'list too large'))
            return
        target.extend(self.mark(items))

    def mark(self, items):
        """Actions added in an unknown branch carry the branch's note."""
        if not self.uncertain:
            return list(items)
        return [self.marked(i) for i in items]

    def marked(self, item):
        if not self.uncertain or not isinstance(item, Action):
            return item
        return Group(actions=[item], scoped=False,
                     notes=[self.uncertain[-1]], location=item.location)

    def truth(self, value):
        """True/False for known values, None otherwise."""
        if isinstance(value, (str, int, float, bool, type(None), list,
                              tuple, dict)):
            if isinstance(value, (list, tuple, dict)) and any(
                    isinstance(v, UnknownValue) for v in value):
                return bool(value) or None
            return bool(value)
        return None

    def sequence(self, value):
        """The items of a known sequence, None when not known."""
        if isinstance(value, (list, tuple, str)):
            items = list(value)
        elif isinstance(value, dict):
            items = list(value)
        else:
            return None
        if len(items) > MAX_LOOP:
            return None
        return items

    def binary(self, op, left, right, node):
        ok = (str, int, float, bool, list, tuple)
        if not isinstance(left, ok) or not isinstance(right, ok):
            if isinstance(left, UnknownValue):
                return left
            if isinstance(right, UnknownValue):
                return right
            return self.unknown(node, f'"{shorten(_source(node), 50)}" '
                                'combines values not known before launch')
        if isinstance(op, ast.Mod) and isinstance(left, str):
            return self.unknown(node, '%-formatting not interpreted')
        scalars = (str, int, float, bool)
        if isinstance(left, scalars) and isinstance(right, scalars):
            # the arithmetic (and limits) of $(eval) and PythonExpression
            try:
                return self.limit(safe_eval.binary(op, left, right), node)
            except Unresolved as e:
                return self.unknown(node, str(e))
        if isinstance(op, ast.Mult):
            for seq, count in ((left, right), (right, left)):
                if isinstance(seq, (str, list, tuple)) and isinstance(
                        count, int) and len(seq) * max(count, 0) > MAX_SIZE:
                    return self.unknown(node, 'value too large')
        if isinstance(op, ast.Pow):
            if abs(right) > 64 if isinstance(right, (int, float)) else True:
                return self.unknown(node, 'power not interpreted')
        function = _BINARY.get(type(op))
        if function is None:
            return self.unknown(node, 'operator not interpreted')
        try:
            value = function(left, right)
        except (TypeError, ValueError, ArithmeticError) as e:
            return self.unknown(node, f'operation fails ({e})')
        return self.limit(value, node)

    # calls

    def call(self, func, args, kwargs, node):
        if isinstance(func, UnknownValue):
            return func
        if isinstance(func, Function):
            return self.call_function(func, args, kwargs, node)
        if isinstance(func, Bound):
            return self.method(func, args, kwargs, node)
        if isinstance(func, Ref):
            return self.library(func.qualname, args, kwargs, node)
        return self.unknown(node, f'call of a {type(func).__name__} not '
                            'interpreted')

    def method(self, bound, args, kwargs, node):
        obj, name = bound.obj, bound.name
        if isinstance(obj, LaunchDescription) and name in (
                'add_action', 'add_entity') and len(args) == 1:
            obj.entities.extend(self.mark(args))
            return None
        if isinstance(obj, list):
            if name == 'append' and len(args) == 1:
                if len(obj) >= MAX_SIZE:
                    return self.unknown(node, 'list too large')
                obj.append(self.marked(args[0]))
                return None
            if name == 'extend' and len(args) == 1:
                items = self.sequence(args[0]) if not isinstance(
                    args[0], (list, tuple)) else list(args[0])
                if items is None:
                    obj.append(self.unknown(node, 'extend with a value not '
                                            'known statically'))
                else:
                    self._grow(obj, items, node)
                return None
            if name == 'insert' and len(args) == 2 and isinstance(
                    args[0], int):
                obj.insert(args[0], self.marked(args[1]))
                return None
            if name == 'copy' and not args:
                return list(obj)
        if isinstance(obj, dict):
            if name == 'items' and not args:
                return [(k, v) for k, v in obj.items()]
            if name == 'keys' and not args:
                return list(obj)
            if name == 'values' and not args:
                return list(obj.values())
            if name == 'get' and 1 <= len(args) <= 2 and _hashable(args[0]):
                return obj.get(args[0], args[1] if len(args) > 1 else None)
            if name == 'update' and len(args) == 1 and isinstance(
                    args[0], dict):
                obj.update(args[0])
                return None
            if name == 'copy' and not args:
                return dict(obj)
        if isinstance(obj, str) and name in _STR_METHODS:
            return self.str_method(obj, name, args, kwargs, node)
        return self.unknown(node, f'method {name}() of a '
                            f'{type(obj).__name__} not interpreted')

    def str_method(self, text, name, args, kwargs, node):
        if name == 'format':
            if not all(isinstance(a, SCALARS) for a in
                       list(args) + list(kwargs.values())):
                return self.unknown(node, 'format() of values not known '
                                    'before launch')
            try:
                fields = [(f, spec or '') for _, f, spec, _ in
                          string.Formatter().parse(text) if f is not None]
            except ValueError:
                return self.unknown(node, 'malformed format string')
            if any(not (f == '' or f.isidentifier() or f.isdigit()) or
                   not _safe_spec(spec) for f, spec in fields):
                return self.unknown(node, 'format fields other than names '
                                    'and positions not interpreted')
            try:
                return self.limit(text.format(*args, **kwargs), node)
            except (IndexError, KeyError, ValueError) as e:
                return self.unknown(node, f'format() fails ({e})')
        if name == 'join' and len(args) == 1 and not kwargs:
            items = self.sequence(args[0])
            if items is None or not all(isinstance(i, str) for i in items):
                return self.unknown(node, 'join() of values not known '
                                    'statically')
            if sum(map(len, items)) + len(text) * len(items) > MAX_SIZE:
                return self.unknown(node, 'value too large')
            return self.limit(text.join(items), node)
        if name == 'replace' and len(args) >= 2 and all(
                isinstance(a, str) for a in args[:2]):
            count = text.count(args[0]) if args[0] else len(text) + 1
            if len(text) + count * len(args[1]) > MAX_SIZE:
                return self.unknown(node, 'value too large')
        if kwargs or not all(isinstance(a, (str, int)) or a is None
                             for a in args):
            return self.unknown(node, f'{name}() arguments not known')
        try:
            value = getattr(text, name)(*args)
        except (TypeError, ValueError) as e:
            return self.unknown(node, f'{name}() fails ({e})')
        return self.limit(value, node)

    def environ(self, name, default, node, *, required=False):
        if not isinstance(name, str):
            return self.unknown(node, 'environment variable name not known')
        if name in self.loader.environ:
            return self.loader.environ[name]
        if required:
            return self.unknown(node, f'environment variable {name} is not '
                                'set')
        return default

    def library(self, qualname, args, kwargs, node):
        module, _, name = qualname.rpartition('.')
        top = qualname.split('.')[0]
        if qualname.startswith('builtins.'):
            return self.builtin(name, args, kwargs, node)
        if top in LAUNCH_MODULES:
            handler = LAUNCH_API.get(name)
            if handler is not None:
                try:
                    return handler(self, Args(args, kwargs), node)
                except ArgError as e:
                    return self.unknown(node, f'{name}(): {e}')
            return self.unknown(node, f'{qualname}() not interpreted')
        if qualname in ('os.path.join', 'os.path.dirname',
                        'os.path.basename', 'os.path.abspath',
                        'os.path.normpath'):
            if kwargs or not all(isinstance(a, str) for a in args) or (
                    not args):
                return self.unknown(node, f'{qualname}() of values not '
                                    'known statically')
            return self.limit(getattr(os.path, name)(*args), node)
        if qualname in ('os.environ.get', 'os.getenv'):
            default = args[1] if len(args) > 1 else kwargs.get('default')
            return self.environ(args[0] if args else None, default, node)
        return self.unknown(node, f'call of {qualname}() not interpreted')

    def builtin(self, name, args, kwargs, node):
        if name in ('str', 'int', 'float', 'bool') and len(args) <= 1 and \
                not kwargs:
            if not args:
                return {'str': '', 'int': 0, 'float': 0.0,
                        'bool': False}[name]
            if isinstance(args[0], SCALARS):
                try:
                    return self.limit(
                        {'str': str, 'int': int, 'float': float,
                         'bool': bool}[name](args[0]), node)
                except (TypeError, ValueError) as e:
                    return self.unknown(node, f'{name}() fails ({e})')
        if name in ('list', 'tuple') and len(args) <= 1 and not kwargs:
            items = self.sequence(args[0]) if args else []
            if items is not None:
                return items if name == 'list' else tuple(items)
        if name == 'dict' and not args:
            return dict(kwargs)
        if name == 'len' and len(args) == 1 and isinstance(
                args[0], (str, list, tuple, dict)):
            return len(args[0])
        if name == 'range' and 1 <= len(args) <= 3 and all(
                isinstance(a, int) for a in args):
            try:
                values = range(*args)
            except ValueError as e:
                return self.unknown(node, f'range() fails ({e})')
            if len(values) > MAX_LOOP:
                return self.unknown(node, 'range() too long')
            return list(values)
        if name in ('enumerate', 'zip', 'sorted', 'reversed') and \
                not kwargs:
            sequences = [self.sequence(a) for a in args]
            if args and all(s is not None for s in sequences):
                if name == 'enumerate' and len(args) == 1:
                    return list(enumerate(sequences[0]))
                if name == 'zip':
                    return list(zip(*sequences))
                if name == 'reversed' and len(args) == 1:
                    return list(reversed(sequences[0]))
                if name == 'sorted' and len(args) == 1 and all(
                        isinstance(v, str) for v in sequences[0]):
                    return sorted(sequences[0])
        if name == 'print':
            return None
        return self.unknown(node, f'{name}() not interpreted')


def _alternatives(name, values, notes):
    """One value for a variable set differently in unknown branches.

    Actions, and lists of actions, are kept: each alternative in a group
    marked with its branch's note. Anything else is unknown.
    """
    def actions(value):
        if value is None or value is MISSING:
            return []
        if isinstance(value, Action):
            return [value]
        if isinstance(value, list) and all(
                isinstance(v, Action) for v in value):
            return list(value)
        return None

    kept = [actions(v) for v in values]
    if all(k is not None for k in kept):
        # what every alternative starts with is not conditional
        common = 0
        while all(len(k) > common and k[common] is kept[0][common]
                  for k in kept):
            common += 1
        groups = list(kept[0][:common]) + [
            Group(actions=k[common:], scoped=False, notes=[note])
            for k, note in zip(kept, notes) if k[common:]]
        if any(isinstance(v, list) for v in values):
            return groups
        return Group(actions=groups, scoped=False)
    return UnknownValue(f'{name} depends on a condition not known '
                        f'statically ({notes[0]})')


def _is_main_guard(test):
    return isinstance(test, ast.Compare) and isinstance(
        test.left, ast.Name) and test.left.id == '__name__'


def _source(node):
    try:
        return ast.unparse(node)
    except Exception:  # ast.unparse of a synthetic node
        return type(node).__name__


def _safe_spec(spec):
    """A format spec without nested fields or huge widths."""
    if '{' in spec or '}' in spec:
        return False
    return all(len(digits) <= 4 for digits in re.findall(r'\d+', spec))


def _hashable(value):
    return isinstance(value, (str, int, float, bool, type(None)))


def _same(a, b):
    if a is b:
        return True
    if isinstance(a, SCALARS) and isinstance(b, SCALARS):
        return type(a) is type(b) and a == b
    return False


def _compare(op, left, right):
    ok = (str, int, float, bool, type(None), list, tuple)
    if not isinstance(left, ok) or not isinstance(right, ok):
        return None
    if any(isinstance(v, UnknownValue) for v in (
            left if isinstance(left, (list, tuple)) else [left])):
        return None
    try:
        if isinstance(op, ast.Eq):
            return left == right
        if isinstance(op, ast.NotEq):
            return left != right
        if isinstance(op, ast.Lt):
            return left < right
        if isinstance(op, ast.LtE):
            return left <= right
        if isinstance(op, ast.Gt):
            return left > right
        if isinstance(op, ast.GtE):
            return left >= right
        if isinstance(op, ast.In):
            return left in right
        if isinstance(op, ast.NotIn):
            return left not in right
        if isinstance(op, (ast.Is, ast.IsNot)):
            if left is not None and right is not None:
                return None
            same = left is right
            return same if isinstance(op, ast.Is) else not same
    except (TypeError, RecursionError):
        return None
    return None


_BINARY = {
    ast.Add: lambda a, b: a + b,
    ast.Sub: lambda a, b: a - b,
    ast.Mult: lambda a, b: a * b,
    ast.Div: lambda a, b: a / b,
    ast.FloorDiv: lambda a, b: a // b,
    ast.Mod: lambda a, b: a % b,
    ast.Pow: lambda a, b: a ** b,
}

_PYTHON_BUILTINS = frozenset(dir(builtins))

_STR_METHODS = frozenset((
    'format', 'join', 'replace', 'lower', 'upper', 'strip', 'lstrip',
    'rstrip', 'split', 'startswith', 'endswith'))


# the launch API
