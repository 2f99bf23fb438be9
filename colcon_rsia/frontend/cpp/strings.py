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
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp.cursors import call_object
from colcon_rsia.frontend.cpp.cursors import child_cursors
from colcon_rsia.frontend.cpp.cursors import expression_text
from colcon_rsia.frontend.cpp.cursors import first_handle
from colcon_rsia.frontend.cpp.cursors import HANDLE_KINDS
from colcon_rsia.frontend.cpp.cursors import handle_marker
from colcon_rsia.frontend.cpp.cursors import is_string
from colcon_rsia.frontend.cpp.cursors import is_written
from colcon_rsia.frontend.cpp.cursors import plain_handle
from colcon_rsia.frontend.cpp.cursors import qualified_name
from colcon_rsia.frontend.cpp.cursors import REF_KINDS
from colcon_rsia.frontend.cpp.cursors import role_argument
from colcon_rsia.frontend.cpp.cursors import same_cursor
from colcon_rsia.frontend.cpp.cursors import VALUE_FUNCTION_KINDS
from colcon_rsia.frontend.cpp.cursors import walk_preorder

CK = ci.CursorKind


class StringVariables:
    """The string variables of one unit and the facts they name."""

    def __init__(self, facts, in_package):  # noqa: D107
        # the unit's facts, which the strings resolve in place
        self.facts = facts
        # whether a declaration is the package's own
        self._in_package = in_package
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
        # the handles (namespace markers) a variable's literal is resolved
        # in: None for a plain literal, else the handle of the resolving
        # call (``out = nh.resolveName("out")``); USR -> markers
        self._resolved_in = {}
        # ``x = nh.resolveName(x)``: USR -> markers x is resolved in again
        self._resolved_again = {}
        # members copied from a parameter of the function setting them
        # (``map_name_(map_name)``): USR -> parameter USRs
        self._copies = {}
        # variables also set to what is neither a literal, a parameter read
        # nor a copy of a parameter
        self._written_otherwise = set()
        # ``x = pub->get_topic_name()``: USR -> endpoint handles read
        self._echoes = {}
        # string variables passed to a package function's parameter that
        # can write them (a non-const reference or pointer) or cannot
        self._passed_writable = set()
        self._passed_read_only = set()

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

    def passed(self, argument, parameter):
        """A package function's `parameter` receives `argument`.

        A string variable passed by value or by const reference keeps its
        value; one passed by non-const reference or pointer may be set by
        the function.
        """
        handle = plain_handle(argument)
        if handle is None or not is_string(handle):
            return
        kind = parameter.type.kind
        writable = kind in _WRITABLE_KINDS and \
            not parameter.type.get_pointee().is_const_qualified()
        (self._passed_writable if writable else self._passed_read_only).add(
            handle.get_usr())

    def resolved_in_place(self, expression):
        """(name, handle marker) of ``nh.resolveName("out")``, or None.

        A name-resolving call with a literal name, given straight to an
        API: the literal in the namespace of the resolving handle.
        """
        resolving = _name_resolving_call(expression)
        if resolving is None:
            return None
        call, api = resolving
        marker = _resolving_marker(
            call, api, lambda member: not self._in_package(member))
        name, literal = written_name(role_argument(
            list(call.get_arguments()), api.name_arg))
        if marker is None or not literal:
            return None
        return name, marker

    def assignment(self, variable, expression):
        """Note what a string variable/field is set to."""
        if not is_string(variable):
            return
        usr = variable.get_usr()
        marker = None
        resolving = _name_resolving_call(expression)
        if resolving is not None:
            # `nh.resolveName("out")`: the name "out" in the handle's
            # namespace, when the handle is known
            call, api = resolving
            marker = _resolving_marker(
                call, api, lambda member: not self._in_package(member))
            expression = role_argument(
                list(call.get_arguments()), api.name_arg)
            if marker is None or expression is None:
                self._written.add(usr)
                self._written_otherwise.add(usr)
                return
            if same_cursor(first_handle(expression), variable) and \
                    string_parts(expression) == [('variable', usr)]:
                self._resolved_again.setdefault(usr, set()).add(marker)
                return
        value, literal = written_name(expression)
        if literal:
            self._values.setdefault(usr, set()).add(value)
            self._resolved_in.setdefault(usr, set()).add(marker)
            return
        if _reads_parameter(expression):
            return  # a fact of its own: see resolve
        self._written.add(usr)
        echoed = _echoed_endpoint(expression)
        if echoed is not None:
            self._echoes.setdefault(usr, set()).add(echoed)
            return
        parts = string_parts(expression)
        # (a member or variable: a parameter set from the caller's own
        # parameter keeps what other callers pass it)
        if resolving is None and parts and len(parts) == 1 and \
                parts[0][0] == 'variable' and \
                not _is_parameter(variable) and \
                _is_parameter(first_handle(expression)):
            self._copies.setdefault(usr, set()).add(parts[0][1])
            return
        self._written_otherwise.add(usr)

    def resolve(self):
        """A name held in a string set only to one literal is that literal.

        ``std::string topic_name_ = "chatter";`` (or set in the
        constructor) then ``create_subscription<M>(topic_name_, ...)``. A
        variable also set otherwise, read from a parameter or handed to a
        function of the package is left as written.
        """
        endpoints = self.facts.publishers + \
            self.facts.subscribers
        bound = self._bound()
        written = (self._written - self._echoed(endpoints)) | {
            r.handle for r in self.facts.param_reads if r.handle} | \
            bound

        def value(handle):
            values = self._values.get(handle)
            if handle in written or not values or len(values) != 1:
                return None
            return next(iter(values))
        for fact in endpoints:
            # (a topic joined around a variable: see _concatenated below)
            topic = None if fact.topic_is_literal or fact.topic_affixes \
                else value(fact.topic_handle)
            marker = self._marker(fact.topic_handle) if topic else None
            if topic and marker is not _AMBIGUOUS:
                fact.topic = topic
                fact.topic_is_literal = True
                fact.topic_handle = None
                fact.nh = fact.nh if marker is None else marker
            elif not fact.topic_is_literal:
                fact.topic_handle = self._copied(fact.topic_handle, bound)
        for call in self.facts.calls:
            # what a call passes to a package function's string parameter
            for argument in call.name_arguments:
                if argument.topic_is_literal:
                    continue
                topic = value(argument.topic_handle)
                prefix, suffix = argument.topic_affixes or ('', '')
                if topic and self._marker(argument.topic_handle) is None \
                        and ros_api.joins_after_node_name(topic, suffix):
                    argument.topic = prefix + topic + suffix
                    argument.topic_is_literal = True
                    argument.topic_handle = None
                    argument.topic_affixes = None
        for fact, handle in self._named_by_variable:
            fact.name = value(handle) or fact.name
        for fact, handle in self._namespaced_by_variable:
            fact.namespace = value(handle) or fact.namespace
        for read, handle in self._defaults_from:
            values = self._values.get(handle, ())
            if handle not in self._written | bound and len(values) == 1:
                read.default = next(iter(values))
        for fact, parts in self._concatenated:
            # (a variable resolved in a handle of its own: left as written)
            values = [text if kind == 'literal' else
                      value(text) if self._marker(text) is None else None
                      for kind, text in parts]
            if any(kind == 'variable' and not ros_api.joins_after_node_name(
                    values[i], ''.join(v or '' for v in values[i + 1:]))
                   for i, (kind, _) in enumerate(parts)):
                continue
            if None not in values:
                fact.topic = ''.join(values)
                fact.topic_is_literal = True
                fact.topic_handle = None

    def _bound(self):
        """String variables a package function may set: passed to it.

        Not those passed only by value or const reference (see passed);
        handles bound otherwise (``std::bind``) count as passed.
        """
        read_only = self._passed_read_only - self._passed_writable
        return {b.handle for b in self.facts.bindings} - read_only

    def _echoed(self, endpoints):
        """Variables set only to the topic name of the endpoint they name.

        ``pub_ = create_publisher<M>(topic_, 1); topic_ =
        pub_->get_topic_name();``: the same topic as before.
        """
        made_with = {}
        for fact in endpoints:
            if fact.handle:
                made_with.setdefault(fact.handle, set()).add(
                    None if fact.topic_is_literal else fact.topic_handle)
        return {usr for usr, handles in self._echoes.items()
                if usr not in self._written_otherwise and
                usr not in self._copies and
                all(made_with.get(h) == {usr} for h in handles)}

    def _marker(self, handle):
        """The handle a variable's literal is resolved in.

        None: the handle that uses the name (a plain literal); a marker:
        the handle of ``resolveName``; _AMBIGUOUS when they differ.
        """
        markers = self._resolved_in.get(handle, {None})
        again = self._resolved_again.get(handle, set())
        if again and markers == {None}:
            markers = again  # `x = "out"; x = nh.resolveName(x);`
        elif again:
            markers = markers | again
        if len(markers) != 1:
            return _AMBIGUOUS
        return next(iter(markers))

    def _copied(self, handle, bound):
        """A member set only to a parameter: that parameter's USR.

        ``Saver(const std::string & map_name) : map_name_(map_name)``:
        the topic is what the callers pass (a literal or a variable read
        from a parameter), resolved per node (package/node_facts.py).
        """
        copies = self._copies.get(handle)
        if not copies or len(copies) != 1 or \
                handle in self._written_otherwise or \
                handle in self._values or handle in bound or \
                any(r.handle == handle
                    for r in self.facts.param_reads):
            return handle
        return next(iter(copies))

    def concatenation(self, facts, literal, argument):
        """Resolve later a topic built with `+` from literals and strings.

        ``ns + "/pose"``, ``std::string("~") + name``,
        ``ros::names::append(ns, "pose")``: when every string variable in
        it is set only to one literal (see resolve); joined from literals
        only (``ros::names::append("arm", "command")``), at once.
        """
        if literal or not facts or argument is None:
            return
        parts = string_parts(argument)
        if parts:
            self._concatenated.append((facts[0], parts))


_ROS1_HANDLE = 'ros::NodeHandle::'
# a marker no handle has: the variable is resolved in several handles
_AMBIGUOUS = object()
# parameter types through which a function can set its caller's string
_WRITABLE_KINDS = frozenset({
    ci.TypeKind.LVALUEREFERENCE, ci.TypeKind.RVALUEREFERENCE,
    ci.TypeKind.POINTER})


def _calls_in(expression):
    """The calls an expression is, through conversions and parentheses."""
    current = expression
    for _ in range(16):
        if current is None:
            return None
        if current.kind == CK.CALL_EXPR and current.referenced is not None \
                and current.spelling not in ('basic_string', 'operator='):
            return current
        children = [c for c in child_cursors(current) if c.kind not in (
            CK.NAMESPACE_REF, CK.TYPE_REF, CK.TEMPLATE_REF)]
        if current.kind not in _STRING_WRAPPERS or len(children) != 1:
            return None
        current = children[0]
    return None


def _name_resolving_call(expression):
    """(call, api) when an expression is a name-resolving call."""
    call = _calls_in(expression)
    if call is None:
        return None
    api = ros_api.lookup_call(qualified_name(call.referenced))
    if api is None or api.role != ros_api.NAME_RESOLVE:
        return None
    return call, api


def _resolving_marker(call, api, foreign):
    """The handle a name-resolving call resolves in, or None (unknown).

    A ROS 1 NodeHandle's ``resolveName``: that handle. ``rclcpp::
    expand_topic_or_service_name(name, node_name, namespace)`` and a
    node's topics interface: the node's namespace ('').
    """
    if not qualified_name(call.referenced).startswith(_ROS1_HANDLE):
        return ''  # a free function or a ROS 2 interface: the node's
    return handle_marker(call_object(call), foreign)


def name_arguments(callee, arguments, in_package):
    """What a call passes to the string parameters of a package function.

    Read as a topic argument of the API would be (see topic_source): the
    callee may make an endpoint's topic of any of them. Only what can name
    a topic: a literal, a parameter read, or a variable of the package (a
    message's field is data, not a name).

    :param in_package: whether a declaration is the package's own
    :rtype: [facts.NameArgument]
    """
    definition = callee.get_definition() or callee
    params = [c for c in definition.get_children() if c.kind == CK.PARM_DECL]
    found = []
    for index, (param, argument) in enumerate(zip(params, arguments)):
        if argument is None or not is_string(param) or \
                not is_written(argument):
            continue
        topic, literal = written_name(argument)
        handle, affixes = (None, None) if literal else topic_source(argument)
        variable = first_handle(argument)
        if not literal and not (handle or '').startswith('param:') and (
                variable is None or not in_package(variable)):
            continue
        found.append(fact_builder.name_argument(
            index=index, topic=topic, topic_is_literal=literal,
            topic_handle=handle, topic_affixes=affixes))
    return found


def topic_source(argument):
    """(handle, affixes): where a non-literal topic argument comes from.

    A variable, or a parameter: ``create_publisher<M>(get_parameter(
    "topic").as_string(), 10)`` reads the parameter in place, recorded
    as ``param:<name>``. A variable joined with literals (``topic +
    "_filtered"``) gives [prefix, suffix] too, so that the value a
    launch file gives the parameter read into it makes the name.
    """
    if argument is None:
        return None, None
    for current in [argument] + list(walk_preorder(argument)):
        if current.kind != CK.CALL_EXPR or current.referenced is None:
            continue
        read = ros_api.lookup_call(qualified_name(current.referenced))
        if read is not None and read.role == ros_api.PARAM_READ:
            param, is_literal = written_name(
                role_argument(list(current.get_arguments()), 0))
            if is_literal:
                return 'param:' + param, None
    parts = string_parts(argument)
    if parts is not None and len(parts) > 1:
        # `ns + "/pose"` is not the value of `ns` alone
        variables = [i for i, (kind, _) in enumerate(parts)
                     if kind == 'variable']
        if len(variables) != 1:
            return None, None
        index = variables[0]
        return parts[index][1], [
            ''.join(text for _, text in parts[:index]),
            ''.join(text for _, text in parts[index + 1:])]
    handle = first_handle(argument)
    return (handle.get_usr() if handle is not None else None), None


def written_name(argument):
    """Return (a name argument as written, is it a literal).

    One string literal and no variable: its text; the node's fully
    qualified name: its private namespace ``~``; else the expression's
    text (not a literal), None for no argument.
    """
    if argument is None:
        return None, False
    if is_node_fqn(argument):
        return '~', True  # the node's own name: its private namespace
    literals = []
    has_variable = False
    for current in [argument] + list(walk_preorder(argument)):
        if current.kind == CK.STRING_LITERAL:
            literals.append(current)
        elif current.kind in REF_KINDS and current.referenced is not None \
                and current.referenced.kind in HANDLE_KINDS:
            has_variable = True
        elif current.kind == CK.CALL_EXPR and \
                current.referenced is not None and \
                current.referenced.kind in VALUE_FUNCTION_KINDS:
            # get_parameter("topic").as_string(): a value, not a name
            has_variable = True
    if len(literals) == 1 and not has_variable:
        return unquote(literals[0].spelling), True
    text = expression_text(argument)
    return (text or None), False


def is_node_fqn(expression):
    """Whether an expression is the node's fully qualified name.

    ``ros::this_node::getName()``, ``node->get_fully_qualified_name()``:
    as a name, the node's private namespace ``~``.
    """
    call = _calls_in(expression)
    if call is None:
        return False
    api = ros_api.lookup_call(qualified_name(call.referenced))
    return api is not None and api.role == ros_api.NODE_FQN


def _echoed_endpoint(expression):
    """The endpoint handle whose topic name an expression reads, or None."""
    call = _calls_in(expression)
    if call is None or qualified_name(call.referenced) not in \
            ros_api.TOPIC_NAME_GETTERS:
        return None
    handle = first_handle(call_object(call))
    return handle.get_usr() if handle is not None else None


def _is_parameter(cursor):
    return cursor is not None and cursor.kind == CK.PARM_DECL


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
