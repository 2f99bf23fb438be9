# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The interpreter of Python launch files: its state, budget and calls.

:class:`Interpreter` walks the functions of a launch file over a subset of
Python (read never run). Its statements, expressions and calls of the
library are parts of it in modules of their own
(:mod:`~colcon_rsia.launch.python_launch_statements`,
:mod:`~colcon_rsia.launch.python_launch_expressions`,
:mod:`~colcon_rsia.launch.python_launch_calls`); here are what they share:
the environments and frames, the budget of steps, the calls of the file's
own functions, and the helpers on values. Its limits are in
:mod:`colcon_rsia.launch.python_launch_values`.
"""

import ast
import builtins
import os

from colcon_rsia import python_arithmetic
from colcon_rsia.launch import safe_eval
from colcon_rsia.launch.common import location
from colcon_rsia.launch.ir import Action
from colcon_rsia.launch.ir import GroupAction
from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.notes import shorten
from colcon_rsia.launch.python_launch_calls import LibraryCalls
from colcon_rsia.launch.python_launch_expressions import Expressions
from colcon_rsia.launch.python_launch_statements import Statements
from colcon_rsia.launch.python_launch_values import Bound
from colcon_rsia.launch.python_launch_values import BranchEnd
from colcon_rsia.launch.python_launch_values import BreakSignal
from colcon_rsia.launch.python_launch_values import BudgetExceeded
from colcon_rsia.launch.python_launch_values import ContinueSignal
from colcon_rsia.launch.python_launch_values import Frame
from colcon_rsia.launch.python_launch_values import Function
from colcon_rsia.launch.python_launch_values import LaunchDescription
from colcon_rsia.launch.python_launch_values import MAX_CALL_DEPTH
from colcon_rsia.launch.python_launch_values import MAX_INT_BITS
from colcon_rsia.launch.python_launch_values import MAX_LOOP
from colcon_rsia.launch.python_launch_values import MAX_POWER
from colcon_rsia.launch.python_launch_values import MAX_SIZE
from colcon_rsia.launch.python_launch_values import MAX_STEPS
from colcon_rsia.launch.python_launch_values import MAX_TOTAL_STEPS
from colcon_rsia.launch.python_launch_values import MISSING
from colcon_rsia.launch.python_launch_values import Ref
from colcon_rsia.launch.python_launch_values import ReturnSignal
from colcon_rsia.launch.python_launch_values import source_text
from colcon_rsia.launch.safe_eval import Unresolved


class Interpreter(Statements, Expressions, LibraryCalls):
    """The state of interpreting one Python launch file."""

    def __init__(self, path, loader):  # noqa: D107
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
        """'path:line' of an AST node of the file."""
        return location(self.path, getattr(node, 'lineno', 0))

    def note(self, node, text):
        """Record a note at an AST node of the file."""
        self.loader.note(f'{self.loc(node)}: {text}')

    def unknown(self, node, text):
        """An unknown value, noted once at file level."""
        self.note(node, text)
        return UnknownValue(f'{self.loc(node)}: {text}')

    def step(self):
        """Spend one step of the file's and the load's budget."""
        self.steps += 1
        self.loader.python_steps += 1
        if self.steps > MAX_STEPS or \
                self.loader.python_steps > MAX_TOTAL_STEPS:
            raise BudgetExceeded()

    def import_(self, stmt, env):
        """Bind the names an import statement binds, as references."""
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
        """Bind a function definition (its defaults evaluated now)."""
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
        """Call a function of the file: bind, run, merge returns."""
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
        """Bind the arguments of a call to the parameters in ``env``."""
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
        """One value of returns in branches not known statically."""
        values = [v for v, _ in conditional] + [final]
        if not all(isinstance(v, LaunchDescription) for v in values):
            return self.unknown(node, 'the function returns different '
                                'values depending on conditions not known '
                                'statically')
        entities = []
        notes = []
        for value, note in conditional:
            entities.append(GroupAction(actions=value.entities, scoped=False,
                                        notes=[note], location=self.loc(node)))
            notes.append(note)
        entities.append(GroupAction(
            actions=final.entities, scoped=False, location=self.loc(node),
            notes=[f'{self.loc(node)}: returned only when an earlier return '
                   f'does not happen ({"; ".join(notes)})']))
        return LaunchDescription(entities)

    # expressions

    def lookup(self, name, env, closure):
        """The value of a name, MISSING when it is not defined."""
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

    # value helpers

    def limit(self, value, node):
        """The value, or an unknown one when it is too large to keep."""
        if isinstance(value, (str, list, tuple)) and len(value) > MAX_SIZE:
            return self.unknown(node, 'value too large')
        if isinstance(value, int) and value.bit_length() > MAX_INT_BITS:
            return self.unknown(node, 'number too large')
        return value

    def grow(self, target, items, node):
        """Extend a list the file builds, within the size limit."""
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
        """An action, in a group with the note of its unknown branch."""
        if not self.uncertain or not isinstance(item, Action):
            return item
        return GroupAction(actions=[item], scoped=False,
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
        """``left <op> right``, within the limits."""
        ok = (str, int, float, bool, list, tuple)
        if not isinstance(left, ok) or not isinstance(right, ok):
            if isinstance(left, UnknownValue):
                return left
            if isinstance(right, UnknownValue):
                return right
            return self.unknown(node, f'"{shorten(source_text(node), 50)}" '
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
            if abs(right) > MAX_POWER if isinstance(right, (int, float)) else True:
                return self.unknown(node, 'power not interpreted')
        function = python_arithmetic.OPERATORS.get(type(op))
        if function is None:
            return self.unknown(node, 'operator not interpreted')
        try:
            value = function(left, right)
        except (TypeError, ValueError, ArithmeticError) as e:
            return self.unknown(node, f'operation fails ({e})')
        return self.limit(value, node)

    # calls

    def call(self, func, args, kwargs, node):
        """Call a value: the file's function, a method or the library."""
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


_PYTHON_BUILTINS = frozenset(dir(builtins))
