# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The expressions of the Python launch interpreter.

A part of :class:`colcon_rsia.launch.python_launch_interpreter.Interpreter`
(its expressions, apart from its statements and calls): an expression's
value is a Python value when known statically, an action or substitution
of :mod:`colcon_rsia.launch.ir` the launch API built, or an
:class:`UnknownValue` saying why not.
"""

import ast

from colcon_rsia.launch.ir import Action
from colcon_rsia.launch.ir import GroupAction
from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.notes import shorten
from colcon_rsia.launch.python_launch_values import Bound
from colcon_rsia.launch.python_launch_values import Function
from colcon_rsia.launch.python_launch_values import HashableValue
from colcon_rsia.launch.python_launch_values import is_hashable
from colcon_rsia.launch.python_launch_values import MAX_CODE_NESTING
from colcon_rsia.launch.python_launch_values import MISSING
from colcon_rsia.launch.python_launch_values import Ref
from colcon_rsia.launch.python_launch_values import safe_format_spec
from colcon_rsia.launch.python_launch_values import same_value
from colcon_rsia.launch.python_launch_values import SCALARS
from colcon_rsia.launch.python_launch_values import source_text


class Expressions:
    """How the interpreter evaluates expressions (a part of the interpreter)."""

    def eval(self, node, env, closure=None, depth=0):
        """The value of an expression (one step of the budget)."""
        self.step()
        if self.nesting >= MAX_CODE_NESTING:
            return self.unknown(node, 'code nested too deeply to interpret')
        method = EXPRESSION_HANDLERS.get(type(node))
        if method is None:
            return self.unknown(
                node, f'{type(node).__name__} expression not interpreted')
        self.nesting += 1
        try:
            return method(self, node, env, closure, depth + 1)
        finally:
            self.nesting -= 1

    def _ex_constant(self, node, env, closure, depth):
        if isinstance(node.value, SCALARS):
            return node.value
        return UnknownValue(f'{self.loc(node)}: constant of type '
                            f'{type(node.value).__name__}')

    def _ex_name(self, node, env, closure, depth):
        value = self.lookup(node.id, env, closure)
        if value is MISSING:
            return self.unknown(node, f"name '{node.id}' is not defined in "
                                'the launch file')
        return value

    def _ex_attribute(self, node, env, closure, depth):
        obj = self.eval(node.value, env, closure, depth)
        if isinstance(obj, Ref):
            return Ref(f'{obj.qualname}.{node.attr}')
        if isinstance(obj, UnknownValue):
            return obj
        if node.attr.startswith('_'):
            return self.unknown(node, f'attribute {node.attr} not '
                                'interpreted')
        return Bound(obj, node.attr)

    def _ex_call(self, node, env, closure, depth):
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

    def _ex_bin_op(self, node, env, closure, depth):
        left = self.eval(node.left, env, closure, depth)
        right = self.eval(node.right, env, closure, depth)
        return self.binary(node.op, left, right, node)

    def _ex_unary_op(self, node, env, closure, depth):
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

    def _ex_bool_op(self, node, env, closure, depth):
        value = None
        for operand in node.values:
            value = self.eval(operand, env, closure, depth)
            truth = self.truth(value)
            if truth is None:
                return UnknownValue(f'{self.loc(node)}: '
                                    f'"{shorten(source_text(node), 50)}" is not '
                                    'known statically')
            if isinstance(node.op, ast.And) and not truth:
                return value
            if isinstance(node.op, ast.Or) and truth:
                return value
        return value

    def _ex_compare(self, node, env, closure, depth):
        left = self.eval(node.left, env, closure, depth)
        for op, right_node in zip(node.ops, node.comparators):
            right = self.eval(right_node, env, closure, depth)
            result = _compare(op, left, right)
            if result is None:
                return UnknownValue(
                    f'{self.loc(node)}: comparison '
                    f'"{shorten(source_text(node), 50)}" not known statically')
            if not result:
                return False
            left = right
        return True

    def _ex_if_exp(self, node, env, closure, depth):
        truth = self.truth(self.eval(node.test, env, closure, depth))
        if truth is True:
            return self.eval(node.body, env, closure, depth)
        if truth is False:
            return self.eval(node.orelse, env, closure, depth)
        text = shorten(source_text(node.test), 50)
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
        if same_value(values[0], values[1]):
            return values[0]
        if all(isinstance(v, Action) or v is None for v in values):
            self.note(node, f'condition "{text}" not known statically; both '
                      'alternatives are read and marked')
            return GroupAction(actions=[
                GroupAction(actions=[v], scoped=False, notes=[note])
                for v, note in zip(values, notes) if v is not None],
                scoped=False, location=self.loc(node))
        return self.unknown(node, f'value depends on "{text}", which is not '
                            'known statically')

    def _ex_joined_str(self, node, env, closure, depth):
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
                if not isinstance(spec, str) or not safe_format_spec(spec):
                    return self.unknown(node, 'format spec not interpreted')
            if value.conversion == ord('r'):
                item = repr(item)
            try:
                parts.append(format(item, spec))
            except (ValueError, TypeError):
                return self.unknown(node, 'f-string format not understood')
        return self.limit(''.join(parts), node)

    def _ex_formatted_value(self, node, env, closure, depth):
        return self._ex_joined_str(ast.JoinedStr(values=[node]), env,
                                   closure, depth)

    def _ex_list(self, node, env, closure, depth):
        out = []
        for elt in node.elts:
            if isinstance(elt, ast.Starred):
                items = self.sequence(self.eval(elt.value, env, closure,
                                                depth))
                if items is None:
                    out.append(self.unknown(elt, 'unpacking of a value not '
                                            'known statically'))
                else:
                    self.grow(out, items, node)
            else:
                out.append(self.eval(elt, env, closure, depth))
        return out

    def _ex_tuple(self, node, env, closure, depth):
        return tuple(self._ex_list(node, env, closure, depth))

    def _ex_set(self, node, env, closure, depth):
        return self._ex_list(node, env, closure, depth)

    def _ex_dict(self, node, env, closure, depth):
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
            if not is_hashable(k):
                k = HashableValue(k)
            out[k] = item
        return out

    def _ex_subscript(self, node, env, closure, depth):
        container = self.eval(node.value, env, closure, depth)
        key = self.eval(node.slice, env, closure, depth)
        if isinstance(container, Ref) and container.qualname == \
                'os.environ':
            return self.environ(key, None, node, required=True)
        if isinstance(container, (list, tuple, str, dict)) and (
                is_hashable(key) or isinstance(key, slice)):
            try:
                return container[key]
            except (KeyError, IndexError, TypeError):
                pass
        return self.unknown(node, f'"{shorten(source_text(node), 50)}" not '
                            'known statically')

    def _ex_slice(self, node, env, closure, depth):
        parts = [None if p is None else self.eval(p, env, closure, depth)
                 for p in (node.lower, node.upper, node.step)]
        if all(p is None or isinstance(p, int) for p in parts):
            return slice(*parts)
        return UnknownValue(f'{self.loc(node)}: slice not known')

    def _ex_lambda(self, node, env, closure, depth):
        defaults = [self.eval(d, env, closure, depth)
                    for d in node.args.defaults]
        return Function(node, defaults, {}, [env] + list(closure or []),
                        'lambda')

    def _ex_named_expr(self, node, env, closure, depth):
        value = self.eval(node.value, env, closure, depth)
        self.assign(node.target, value, env, closure)
        return value

    def _ex_list_comp(self, node, env, closure, depth):
        out = []
        self.comprehension(node, node.generators, 0, dict(env), closure,
                           depth, lambda e: out.append(
                               self.eval(node.elt, e, closure, depth)))
        return out

    def _ex_dict_comp(self, node, env, closure, depth):
        out = {}

        def add(e):
            key = self.eval(node.key, e, closure, depth)
            out[key if is_hashable(key) else HashableValue(key)] = self.eval(
                node.value, e, closure, depth)
        self.comprehension(node, node.generators, 0, dict(env), closure,
                           depth, add)
        return out

    def comprehension(self, node, generators, index, env, closure, depth,
                      emit):
        """Emit the environments of a comprehension's generators."""
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
                            f'"{shorten(source_text(condition), 50)}", which is '
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


# the expressions interpreted; any other is an unknown value
EXPRESSION_HANDLERS = {
    ast.Constant: Expressions._ex_constant,
    ast.Name: Expressions._ex_name,
    ast.Attribute: Expressions._ex_attribute,
    ast.Call: Expressions._ex_call,
    ast.BinOp: Expressions._ex_bin_op,
    ast.UnaryOp: Expressions._ex_unary_op,
    ast.BoolOp: Expressions._ex_bool_op,
    ast.Compare: Expressions._ex_compare,
    ast.IfExp: Expressions._ex_if_exp,
    ast.JoinedStr: Expressions._ex_joined_str,
    ast.FormattedValue: Expressions._ex_formatted_value,
    ast.List: Expressions._ex_list,
    ast.Tuple: Expressions._ex_tuple,
    ast.Set: Expressions._ex_set,
    ast.Dict: Expressions._ex_dict,
    ast.Subscript: Expressions._ex_subscript,
    ast.Slice: Expressions._ex_slice,
    ast.Lambda: Expressions._ex_lambda,
    ast.NamedExpr: Expressions._ex_named_expr,
    ast.ListComp: Expressions._ex_list_comp,
    ast.SetComp: Expressions._ex_list_comp,
    ast.GeneratorExp: Expressions._ex_list_comp,
    ast.DictComp: Expressions._ex_dict_comp,
}
