# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A tiny expression evaluator for ``$(eval …)`` and ``PythonExpression``.

The expression is parsed with :func:`ast.parse` and only a small subset is
interpreted: literals, arithmetic, comparisons, ``and``/``or``/``not``,
conditional expressions, string concatenation, the conversions ``str``,
``int``, ``float`` and ``bool``, bare argument names and a few lookup
functions (``arg('x')``…) supplied by the caller. Nothing is ever handed to
Python's ``eval``.
"""

import ast
import operator

from colcon_rsia import python_arithmetic
from colcon_rsia.launch.notes import shorten


class Unresolved(Exception):
    """A value that cannot be determined statically (the message says why)."""


# an expression longer than this is not a launch-file expression; the
# limit also keeps ast.parse far from its nesting limits
MAX_EXPRESSION_LENGTH = 2000
# nesting depth of the evaluated tree: expressions nest a few levels; at
# two Python frames a level the stack stays well below its limit of 1000
MAX_DEPTH = 100
# the strings and numbers an expression may build: the limits of
# colcon_rsia.python_arithmetic, shared with the Python front end

_COMPARE = {
    ast.Eq: operator.eq,
    ast.NotEq: operator.ne,
    ast.Lt: operator.lt,
    ast.LtE: operator.le,
    ast.Gt: operator.gt,
    ast.GtE: operator.ge,
    ast.In: lambda a, b: operator.contains(b, a),
    ast.NotIn: lambda a, b: not operator.contains(b, a),
}

_SCALARS = (str, int, float, bool, type(None))
# conversions between the scalar types (no other built-in is reachable)
_CONVERSIONS = {'str': str, 'int': int, 'float': float, 'bool': bool}


def evaluate(expression, *, lookup=None, functions=None):
    """Evaluate an expression of the safe subset.

    :param str expression: the expression text
    :param lookup: callable name -> value for bare names (raises
      :class:`Unresolved` for unknown ones); None: no names are known
    :param dict functions: name -> callable for calls such as ``arg('x')``
    :returns: the value (str, int, float, bool or None)
    :raises Unresolved: for anything outside the subset or not known
    """
    if not isinstance(expression, str):
        raise Unresolved('the expression is not a string')
    text = expression.strip()
    if len(text) > MAX_EXPRESSION_LENGTH:
        raise Unresolved('the expression is too long to evaluate')
    try:
        tree = ast.parse(text, mode='eval')
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        raise Unresolved(f'not a valid expression: {shorten(text)}')
    evaluator = _Evaluator(lookup, functions or {})
    return evaluator.eval(tree.body, 0)


def to_text(value):
    """The text an evaluated expression substitutes (``str()`` of it)."""
    try:
        text = str(value)
    except ValueError:  # an int beyond Python's str conversion limit
        raise Unresolved('the expression value is too large')
    return text


def _check(value):
    try:
        python_arithmetic.check(value)
    except python_arithmetic.Refused as e:
        raise Unresolved(str(e))
    if not isinstance(value, _SCALARS):
        raise Unresolved('the expression builds an unsupported value')
    return value


class _Evaluator:

    def __init__(self, lookup, functions):
        self.lookup = lookup
        self.functions = functions

    def eval(self, node, depth):
        if depth > MAX_DEPTH:
            raise Unresolved('the expression is nested too deeply')
        method = _NODE_HANDLERS.get(type(node))
        if method is None:
            raise Unresolved(
                f'{type(node).__name__} is not supported in expressions')
        return _check(method(self, node, depth + 1))

    def _constant(self, node, depth):
        if not isinstance(node.value, _SCALARS):
            raise Unresolved('only text, numbers and booleans are supported')
        return node.value

    def _name(self, node, depth):
        if self.lookup is None:
            raise Unresolved(f"unknown name '{node.id}'")
        return self.lookup(node.id)

    def _bin_op(self, node, depth):
        if type(node.op) not in python_arithmetic.OPERATORS:
            raise Unresolved('operator not supported in expressions')
        left = self.eval(node.left, depth)
        right = self.eval(node.right, depth)
        return binary(node.op, left, right)

    def _unary_op(self, node, depth):
        value = self.eval(node.operand, depth)
        if isinstance(node.op, ast.Not):
            return not value
        if isinstance(value, str) or value is None:
            raise Unresolved('unary sign of a non-number')
        if isinstance(node.op, ast.USub):
            return -value
        if isinstance(node.op, ast.UAdd):
            return +value
        raise Unresolved('operator not supported in expressions')

    def _bool_op(self, node, depth):
        value = None
        for operand in node.values:
            value = self.eval(operand, depth)
            if isinstance(node.op, ast.And) and not value:
                return value
            if isinstance(node.op, ast.Or) and value:
                return value
        return value

    def _compare(self, node, depth):
        left = self.eval(node.left, depth)
        for op_node, right_node in zip(node.ops, node.comparators):
            op = _COMPARE.get(type(op_node))
            if op is None:
                raise Unresolved('comparison not supported in expressions')
            right = self.eval(right_node, depth)
            try:
                result = op(left, right)
            except TypeError as e:
                raise Unresolved(f'the comparison fails: {e}')
            if not result:
                return False
            left = right
        return True

    def _if_exp(self, node, depth):
        if self.eval(node.test, depth):
            return self.eval(node.body, depth)
        return self.eval(node.orelse, depth)

    def _call(self, node, depth):
        if not isinstance(node.func, ast.Name) or node.keywords:
            raise Unresolved('only simple calls such as arg(…) are supported')
        function = self.functions.get(node.func.id,
                                      _CONVERSIONS.get(node.func.id))
        if function is None:
            raise Unresolved(f"unknown function '{node.func.id}'")
        args = []
        for a in node.args:
            if isinstance(a, ast.Starred):
                raise Unresolved('unpacking is not supported')
            args.append(self.eval(a, depth))
        try:
            return function(*args)
        except (TypeError, ValueError, ArithmeticError) as e:
            raise Unresolved(f'{node.func.id}() fails: {e}')


# the nodes of the subset; any other is not supported
_NODE_HANDLERS = {
    ast.Constant: _Evaluator._constant,
    ast.Name: _Evaluator._name,
    ast.BinOp: _Evaluator._bin_op,
    ast.UnaryOp: _Evaluator._unary_op,
    ast.BoolOp: _Evaluator._bool_op,
    ast.Compare: _Evaluator._compare,
    ast.IfExp: _Evaluator._if_exp,
    ast.Call: _Evaluator._call,
}


def binary(op, left, right):
    """``left <op> right`` of two scalars (:mod:`colcon_rsia.python_arithmetic`).

    The one arithmetic of launch files: ``$(eval …)``,
    ``PythonExpression`` and the Python launch interpreter use it.

    :param op: an :mod:`ast` operator (``ast.Add()``…)
    :raises Unresolved: an operator not supported, a value too large, or
      an operation that fails
    """
    try:
        return python_arithmetic.binary(op, left, right)
    except python_arithmetic.Refused as e:
        raise Unresolved(str(e))
