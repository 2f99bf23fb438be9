# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The statements of the Python launch interpreter.

A part of :class:`colcon_rsia.launch.python_launch_interpreter.Interpreter`
(its statements, apart from its expressions and calls): a statement runs
in an environment, and an ``if`` or loop over what is not known statically
runs its alternatives from the same state and merges what they leave.
"""

import ast

from colcon_rsia.launch.ir import Action
from colcon_rsia.launch.ir import GroupAction
from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.notes import shorten
from colcon_rsia.launch.python_launch_values import BranchEnd
from colcon_rsia.launch.python_launch_values import BreakSignal
from colcon_rsia.launch.python_launch_values import ContinueSignal
from colcon_rsia.launch.python_launch_values import is_hashable
from colcon_rsia.launch.python_launch_values import MAX_CODE_NESTING
from colcon_rsia.launch.python_launch_values import MISSING
from colcon_rsia.launch.python_launch_values import ReturnSignal
from colcon_rsia.launch.python_launch_values import same_value
from colcon_rsia.launch.python_launch_values import source_text


class Statements:
    """How the interpreter runs statements (a part of the interpreter)."""

    def block(self, body, env, closure=None):
        """Run statements in order."""
        for stmt in body:
            self.statement(stmt, env, closure)

    def statement(self, stmt, env, closure=None):
        """Run a statement; each is one step of the budget."""
        self.step()
        kind = type(stmt).__name__
        method = STATEMENT_HANDLERS.get(type(stmt))
        if method is None:
            self.note(stmt, f'{kind} statement not interpreted')
            return
        if self.nesting >= MAX_CODE_NESTING:
            self.note(stmt, 'code nested too deeply to interpret')
            return
        self.nesting += 1
        try:
            method(self, stmt, env, closure)
        finally:
            self.nesting -= 1

    def _stmt_expr(self, stmt, env, closure):
        self.eval(stmt.value, env, closure)

    def _stmt_pass(self, stmt, env, closure):
        pass

    def _stmt_import(self, stmt, env, closure):
        self.import_(stmt, env)

    def _stmt_function_def(self, stmt, env, closure):
        self.define(stmt, env, [env] + list(closure or [self.globals]))

    def _stmt_return(self, stmt, env, closure):
        value = None if stmt.value is None else self.eval(stmt.value, env,
                                                          closure)
        frame = self.frames[-1] if self.frames else None
        if frame is not None and len(self.uncertain) > frame.base:
            frame.conditional_returns.append((value, self.uncertain[-1]))
            raise BranchEnd()  # ends this branch only
        raise ReturnSignal(value)

    def _stmt_break(self, stmt, env, closure):
        raise BreakSignal()

    def _stmt_continue(self, stmt, env, closure):
        raise ContinueSignal()

    def _stmt_assign(self, stmt, env, closure):
        value = self.eval(stmt.value, env, closure)
        for target in stmt.targets:
            self.assign(target, value, env, closure)

    def _stmt_ann_assign(self, stmt, env, closure):
        if stmt.value is not None:
            self.assign(stmt.target, self.eval(stmt.value, env, closure),
                        env, closure)

    def _stmt_aug_assign(self, stmt, env, closure):
        current = self.eval(stmt.target, env, closure)
        value = self.eval(stmt.value, env, closure)
        if isinstance(current, list) and isinstance(stmt.op, ast.Add):
            if isinstance(value, (list, tuple)):
                self.grow(current, value, stmt)
                return
        result = self.binary(stmt.op, current, value, stmt)
        self.assign(stmt.target, result, env, closure)

    def _stmt_if(self, stmt, env, closure):
        test = self.truth(self.eval(stmt.test, env, closure))
        if test is True:
            self.block(stmt.body, env, closure)
        elif test is False:
            self.block(stmt.orelse, env, closure)
        else:
            text = shorten(source_text(stmt.test), 50)
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
            if all(same_value(first, v) for v in values[1:]):
                if first is not MISSING:
                    env[name] = first
            else:
                env[name] = _alternatives(name, values, notes)

    def _stmt_for(self, stmt, env, closure):
        iterable = self.eval(stmt.iter, env, closure)
        items = self.sequence(iterable)
        if items is None:
            text = shorten(source_text(stmt.iter), 50)
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

    def _stmt_while(self, stmt, env, closure):
        test = self.truth(self.eval(stmt.test, env, closure))
        if test is False:
            self.block(stmt.orelse, env, closure)
            return
        note = (f'{self.loc(stmt)}: created in a while loop (listed once, '
                'it may run any number of times)')
        self.note(stmt, 'while loop read once; what it starts is marked')
        self.branches(env, closure, [(stmt.body, note), ([], note)])

    def _stmt_with(self, stmt, env, closure):
        for item in stmt.items:
            self.eval(item.context_expr, env, closure)
            if item.optional_vars is not None:
                self.assign(item.optional_vars,
                            self.unknown(stmt, 'value of a with statement'),
                            env, closure)
        self.block(stmt.body, env, closure)

    def _stmt_try(self, stmt, env, closure):
        self.block(stmt.body, env, closure)
        self.block(stmt.orelse, env, closure)
        self.block(stmt.finalbody, env, closure)

    def _stmt_assert(self, stmt, env, closure):
        pass

    def _stmt_raise(self, stmt, env, closure):
        self.note(stmt, 'raise not interpreted')

    def _stmt_global(self, stmt, env, closure):
        pass

    def _stmt_delete(self, stmt, env, closure):
        for target in stmt.targets:
            if isinstance(target, ast.Name):
                env.pop(target.id, None)

    # assignment

    def assign(self, target, value, env, closure):
        """Assign a value to a target (name, unpacking or item)."""
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
            if isinstance(container, dict) and is_hashable(key):
                container[key] = value
            elif isinstance(container, list) and isinstance(key, int) and \
                    -len(container) <= key < len(container):
                container[key] = value
            else:
                self.note(target, 'assignment to an item not interpreted')
        else:
            self.note(target, f'assignment to {type(target).__name__} not '
                      'interpreted')


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
            GroupAction(actions=k[common:], scoped=False, notes=[note])
            for k, note in zip(kept, notes) if k[common:]]
        if any(isinstance(v, list) for v in values):
            return groups
        return GroupAction(actions=groups, scoped=False)
    return UnknownValue(f'{name} depends on a condition not known '
                        f'statically ({notes[0]})')


# the statements interpreted; any other is noted and skipped
STATEMENT_HANDLERS = {
    ast.Expr: Statements._stmt_expr,
    ast.Pass: Statements._stmt_pass,
    ast.Import: Statements._stmt_import,
    ast.ImportFrom: Statements._stmt_import,
    ast.FunctionDef: Statements._stmt_function_def,
    ast.Return: Statements._stmt_return,
    ast.Break: Statements._stmt_break,
    ast.Continue: Statements._stmt_continue,
    ast.Assign: Statements._stmt_assign,
    ast.AnnAssign: Statements._stmt_ann_assign,
    ast.AugAssign: Statements._stmt_aug_assign,
    ast.If: Statements._stmt_if,
    ast.For: Statements._stmt_for,
    ast.While: Statements._stmt_while,
    ast.With: Statements._stmt_with,
    ast.Try: Statements._stmt_try,
    ast.Assert: Statements._stmt_assert,
    ast.Raise: Statements._stmt_raise,
    ast.Global: Statements._stmt_global,
    ast.Nonlocal: Statements._stmt_global,
    ast.Delete: Statements._stmt_delete,
}
