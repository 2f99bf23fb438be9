# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The arithmetic of the Python expressions colcon-rsia reads, with limits.

One set of rules for every place that evaluates Python written in the
analysed workspace: ``$(eval …)`` and ``PythonExpression`` of launch files,
the interpreter of ``.launch.py`` files, and the numbers of the Python
front end (a rate, a period). Nothing is handed to Python's ``eval``; an
operation that would build a huge string or number is refused rather than
computed.
"""

import ast
import math
import operator

# longest string an expression may build ('x' * 10 ** 9 must not run)
MAX_STRING_LENGTH = 100000
# largest magnitude of a number an expression may build: about the largest
# float, beyond which arithmetic overflows or big integers get slow
MAX_NUMBER = 10 ** 308

# the binary operators interpreted, by ast operator type
OPERATORS = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv,
    ast.Mod: operator.mod,
    ast.Pow: operator.pow,
}


class Refused(ValueError):
    """An operation not interpreted, too large, or failing (says which)."""


def binary(op, left, right):
    """``left <op> right`` of two scalars, within the limits above.

    :param op: an :mod:`ast` operator (``ast.Add()``…)
    :raises Refused: an operator not interpreted (also ``%``-formatting of
      a string), a value too large, or an operation that fails
    """
    function = OPERATORS.get(type(op))
    if function is None:
        raise Refused('operator not supported in expressions')
    if isinstance(op, ast.Mod) and isinstance(left, str):
        raise Refused('string formatting is not supported')
    if isinstance(op, ast.Mult):
        _check_repeat(left, right)
        _check_repeat(right, left)
    if isinstance(op, ast.Pow):
        _check_power(left, right)
    try:
        return check(function(left, right))
    except (TypeError, ValueError, ArithmeticError) as e:
        if isinstance(e, Refused):
            raise
        raise Refused(f'the expression fails: {e}')


def check(value):
    """The value itself when within the limits, else :class:`Refused`."""
    if isinstance(value, str) and len(value) > MAX_STRING_LENGTH:
        raise Refused('the expression builds a string that is too long')
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if isinstance(value, float) and math.isnan(value):
            return value
        if abs(value) > MAX_NUMBER:
            raise Refused('the expression builds a number that is too large')
    return value


def _check_repeat(text, count):
    if isinstance(text, str) and isinstance(count, int):
        if count > 0 and len(text) * count > MAX_STRING_LENGTH:
            raise Refused('the expression builds a string that is too long')


def _check_power(base, exponent):
    if not all(isinstance(v, (int, float)) for v in (base, exponent)):
        return
    if base in (0, 1, -1) or exponent == 0:
        return
    try:
        magnitude = abs(float(exponent)) * math.log10(abs(float(base)))
    except (OverflowError, ValueError):
        raise Refused('the power is too large')
    if magnitude > 308:
        raise Refused('the power is too large')
