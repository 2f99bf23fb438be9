# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the strings of a unit hold: names written as string variables.

A topic, service or namespace is often not written as a literal at the
call but kept in a string variable (``std::string topic_name_ =
"chatter";``) or joined with ``+``. :class:`StringVariables` gathers what
each string variable is set to during the walk and, at its end, puts the
one literal a variable is only ever set to in the facts that named it.
:func:`string_parts` reads the pieces a string expression is joined from.
"""

import re

import clang.cindex as ci
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp.cursors import child_cursors
from colcon_rsia.frontend.cpp.cursors import HANDLE_KINDS
from colcon_rsia.frontend.cpp.cursors import is_string
from colcon_rsia.frontend.cpp.cursors import qualified_name
from colcon_rsia.frontend.cpp.cursors import REF_KINDS

CK = ci.CursorKind


class StringVariables:
    """The string variables of one unit and the facts they name."""

    def __init__(self, walker):  # noqa: D107
        self.walker = walker
        # string variables/fields: the literals they are set to, and those
        # also set otherwise (see resolve)
        self._values = {}
        self._written = set()
        # (service fact, variable its name is read from)
        self._named_by_variable = []
        # NodeHandles made from a string variable: (fact, its USR)
        self._namespaced_by_variable = []
        # endpoint facts whose topic is built by `+`: (fact, parts)
        self._concatenated = []
        # parameter reads whose default is a string variable: (read, USR)
        self._defaults_from = []

    def name_from(self, fact, variable):
        """A service fact whose name is the value of `variable` (a USR)."""
        self._named_by_variable.append((fact, variable))

    def default_from(self, read, variable):
        """A parameter read whose default is the value of `variable`.

        ``scan_topic_ = "/scan"; scan_topic_ = declare_parameter(
        "scan_topic", scan_topic_);``: the variable's one literal, though
        the read itself writes the variable.
        """
        self._defaults_from.append((read, variable))

    def namespace_from(self, fact, variable):
        """A NodeHandle fact whose namespace is the value of `variable`."""
        self._namespaced_by_variable.append((fact, variable))

    def assignment(self, variable, expression):
        """Note what a string variable/field is set to."""
        if not is_string(variable):
            return
        value, literal = self.walker.topic(expression)
        if literal:
            self._values.setdefault(
                variable.get_usr(), set()).add(value)
        elif not _reads_parameter(expression):
            # (a parameter read is a fact of its own: see resolve)
            self._written.add(variable.get_usr())

    def resolve(self):
        """A name held in a string set only to one literal is that literal.

        ``std::string topic_name_ = "chatter";`` (or set in the
        constructor) then ``create_subscription<M>(topic_name_, ...)``. A
        variable also set otherwise, read from a parameter or handed to a
        function of the package is left as written.
        """
        written = self._written | {
            r.handle for r in self.walker.facts.param_reads if r.handle} | {
            b.handle for b in self.walker.facts.bindings}

        def value(handle):
            values = self._values.get(handle)
            if handle in written or not values or len(values) != 1:
                return None
            return next(iter(values))
        for fact in self.walker.facts.publishers + self.walker.facts.subscribers:
            # (a topic joined around a variable: see _concatenated below)
            topic = None if fact.topic_is_literal or fact.topic_affixes \
                else value(fact.topic_handle)
            if topic:
                fact.topic = topic
                fact.topic_is_literal = True
                fact.topic_handle = None
        for fact, handle in self._named_by_variable:
            fact.name = value(handle) or fact.name
        for fact, handle in self._namespaced_by_variable:
            fact.namespace = value(handle) or fact.namespace
        bound = {b.handle for b in self.walker.facts.bindings}
        for read, handle in self._defaults_from:
            values = self._values.get(handle, ())
            if handle not in self._written | bound and len(values) == 1:
                read.default = next(iter(values))
        for fact, parts in self._concatenated:
            values = [text if kind == 'literal' else value(text)
                      for kind, text in parts]
            if None not in values:
                fact.topic = ''.join(values)
                fact.topic_is_literal = True
                fact.topic_handle = None

    def concatenation(self, facts, literal, argument):
        """Resolve later a topic built with `+` from literals and strings.

        ``ns + "/pose"``, ``std::string("~") + name``,
        ``ros::names::append(ns, "pose")``: when every string variable in
        it is set only to one literal (see resolve).
        """
        if literal or not facts or argument is None:
            return
        parts = string_parts(argument)
        if parts and any(kind == 'variable' for kind, _ in parts):
            self._concatenated.append((facts[0], parts))


def _reads_parameter(expression):
    """Whether an expression is a call reading a parameter's value."""
    for current in [expression] + list(expression.walk_preorder()):
        if current.kind == CK.CALL_EXPR and current.referenced is not None:
            api = ros_api.lookup_call(qualified_name(current.referenced))
            return api is not None and api.role == ros_api.PARAM_READ
    return False


# what a string expression may pass through on its way to a literal or a
# variable: conversions, parentheses, std::string(...) temporaries
_STRING_WRAPPERS = frozenset({
    CK.UNEXPOSED_EXPR, CK.PAREN_EXPR, CK.CXX_FUNCTIONAL_CAST_EXPR,
    CK.CALL_EXPR, CK.CSTYLE_CAST_EXPR})
_NAMES_APPEND = 'ros::names::append'


def string_parts(expression, depth=0):
    """[('literal', text) | ('variable', usr)] a string is joined from.

    None when it holds anything else (a call, a parameter read).
    """
    if expression is None or depth > 32:
        return None
    kind = expression.kind
    if kind == CK.STRING_LITERAL:
        return [('literal', unquote(expression.spelling))]
    if kind in REF_KINDS and expression.referenced is not None and \
            expression.referenced.kind in HANDLE_KINDS:
        return [('variable', expression.referenced.get_usr())] \
            if is_string(expression) else None
    if kind == CK.CALL_EXPR:
        name = qualified_name(expression.referenced) \
            if expression.referenced is not None else ''
        arguments = list(expression.get_arguments())
        if expression.spelling == 'operator+' and len(arguments) == 2:
            left, right = (string_parts(a, depth + 1) for a in arguments)
            return left + right if left and right else None
        if name == _NAMES_APPEND and len(arguments) == 2:
            left, right = (string_parts(a, depth + 1) for a in arguments)
            return left + [('literal', '/')] + right \
                if left and right else None
        if expression.spelling == 'basic_string' and arguments:
            # std::string(text): the constructor (its allocator defaulted)
            return string_parts(arguments[0], depth + 1)
    children = [c for c in child_cursors(expression) if c.kind not in (
        CK.NAMESPACE_REF, CK.TYPE_REF, CK.TEMPLATE_REF)]
    if kind in _STRING_WRAPPERS and len(children) == 1:
        return string_parts(children[0], depth + 1)
    return None


def unquote(literal):
    """The text of a string literal as written, without its quotes."""
    match = re.match(r'^(?:u8|u|U|L)?"(.*)"$', literal, re.DOTALL)
    return match.group(1) if match else literal
