# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Publishing every n-th call: ``if (++count % n == 0) pub.publish(m);``.

A decimating callback publishes at 1/n of its input's rate when `n` is a
literal or a constant. Only the nearest enclosing ``if`` of the publish
call is read, and only its then-branch counts: anything else (another
condition, an ``else`` branch) is not a decimation we can count.
"""

import clang.cindex as ci
from colcon_rsia.frontend.cpp.const_eval import binary_operator
from colcon_rsia.frontend.cpp.const_eval import evaluate_number

CK = ci.CursorKind

_WRAPPERS = frozenset({CK.UNEXPOSED_EXPR, CK.PAREN_EXPR})


def every_nth(stack):
    """`n` when the publish call under `stack` runs every n-th time."""
    for index in range(len(stack) - 1, 0, -1):
        parent = stack[index - 1]
        if parent.kind in (CK.SWITCH_STMT, CK.CONDITIONAL_OPERATOR):
            return None
        if parent.kind != CK.IF_STMT:
            continue
        children = list(parent.get_children())
        # the then-branch is the child after the condition
        if len(children) < 2 or stack[index] != children[1]:
            return None
        return _modulo_is_zero(children[0])
    return None


def _unwrap(cursor):
    while cursor.kind in _WRAPPERS:
        children = list(cursor.get_children())
        if len(children) != 1:
            break
        cursor = children[0]
    return cursor


def _modulo_is_zero(condition):
    condition = _unwrap(condition)
    children = list(condition.get_children())
    if condition.kind != CK.BINARY_OPERATOR or len(children) != 2 or \
            binary_operator(condition, children[0]) != '==':
        return None
    for modulo, zero in (children, children[::-1]):
        modulo = _unwrap(modulo)
        parts = list(modulo.get_children())
        if modulo.kind == CK.BINARY_OPERATOR and len(parts) == 2 and \
                binary_operator(modulo, parts[0]) == '%' and \
                evaluate_number(zero) == 0:
            n = evaluate_number(parts[1])
            if n is not None and n == int(n) and n >= 1:
                return int(n)
    return None
