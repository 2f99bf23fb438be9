# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Callbacks and what calls bind to a package function's parameters.

A helper of the C++ walker, given what it uses (see :mod:`.questions`):
which function a callback argument designates (a lambda, ``&C::m``, a
bind expression, a ``std::function`` variable resolved at the end of the
walk), and what a call passes to the parameters of the package's functions (handles,
string literals, callables), so that a helper's registrations take its
callers' names and callbacks.
"""

import re

import clang.cindex as ci
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend.cpp.cursors import first_function
from colcon_rsia.frontend.cpp.cursors import FUNCTION_KINDS
from colcon_rsia.frontend.cpp.cursors import HANDLE_KINDS
from colcon_rsia.frontend.cpp.cursors import is_callable_argument
from colcon_rsia.frontend.cpp.cursors import is_node_handle
from colcon_rsia.frontend.cpp.cursors import is_string
from colcon_rsia.frontend.cpp.cursors import is_written
from colcon_rsia.frontend.cpp.cursors import plain_handle
from colcon_rsia.frontend.cpp.cursors import qualified_name
from colcon_rsia.frontend.cpp.cursors import REF_KINDS
from colcon_rsia.frontend.cpp.cursors import template_member
from colcon_rsia.frontend.cpp.cursors import walk_preorder
from colcon_rsia.frontend.cpp.hosted import node_handle_marker
from colcon_rsia.frontend.cpp.strings import written_name

CK = ci.CursorKind
BIND_FUNCTIONS = frozenset({'boost::bind', 'std::bind'})

CALLABLE_PREFIX = 'callable:'
_CALLABLE_TYPE = re.compile(r'\b(?:std|boost)::(?:function<|_Bind<)')


def is_callable(cursor):
    """A variable/field holding a callable: std::function, bind results."""
    return bool(_CALLABLE_TYPE.search(cursor.type.get_canonical().spelling))


# types no callable converts to: a NodeHandle or name a constructor takes
# beside its callback (SimpleActionServer(nh, name, callback, ...))
_NOT_CALLABLE_KINDS = frozenset({
    ci.TypeKind.BOOL, ci.TypeKind.INT, ci.TypeKind.UINT, ci.TypeKind.LONG,
    ci.TypeKind.ULONG, ci.TypeKind.LONGLONG, ci.TypeKind.ULONGLONG,
    ci.TypeKind.FLOAT, ci.TypeKind.DOUBLE, ci.TypeKind.ENUM})


def _holds_no_callable(parameter):
    """Whether a parameter's type is one no callback can have."""
    canonical = parameter.type.get_canonical()
    if canonical.kind in (ci.TypeKind.LVALUEREFERENCE,
                          ci.TypeKind.RVALUEREFERENCE):
        canonical = canonical.get_pointee()
    if is_callable(parameter) or is_callable_argument(parameter):
        return False  # (a signature may name a string: not the type's)
    return canonical.kind in _NOT_CALLABLE_KINDS or \
        is_node_handle(parameter) or is_string(parameter)


class Callbacks:
    """The callbacks of one walk and what calls bind to parameters.

    Given what it uses: the unit's facts, where cursors are
    (:class:`~colcon_rsia.frontend.cpp.questions.Places`) and the string
    variables (:class:`~colcon_rsia.frontend.cpp.strings.StringVariables`).
    The walker reads :attr:`consumed`, :attr:`registered` and
    :attr:`stored_then_registered`.
    """

    def __init__(self, facts, places, string_variables):  # noqa: D107
        self.facts = facts
        self.places = places
        self.string_variables = string_variables
        # callables stored in std::function variables/fields:
        # {variable USR: function ids assigned to it}
        self._callables = {}
        # places.key() of expressions used as a registered callback, so
        # that they do not also count as a plain function reference
        self.consumed = set()
        # function ids registered as a callback
        self.registered = set()
        # callbacks an options object held before it was registered
        # (`createTimer(ops)`): named, not called, where the object was made
        self.stored_then_registered = set()

    def resolve_stored_callbacks(self):
        """Replace ``callable:<usr>`` callbacks by what was stored there.

        A callback kept in a ``std::function`` member is registered by
        naming the member; the function is what the code assigned to it
        (anywhere in the TU, before or after the registration).
        """
        def resolve(callback):
            if callback and callback.startswith(CALLABLE_PREFIX):
                stored = self._callables.get(callback[len(CALLABLE_PREFIX):])
                return sorted(stored)[0] if stored else None
            return callback
        for fact in (self.facts.subscribers + self.facts.timers +
                     self.facts.services + self.facts.registrations):
            fact.callback = resolve(fact.callback)
        for fact in self.facts.actions:
            fact.callbacks = [c for c in map(resolve, fact.callbacks) if c]
        for fact in self.facts.publishers:
            fact.status_callbacks = [
                c for c in map(resolve, fact.status_callbacks) if c]

    def store_callable(self, variable, expression, consume=True):
        """Remember what a std::function variable/field is set to."""
        callback, _ = self.resolve_callback(expression, consume=consume)
        if callback and not callback.startswith(CALLABLE_PREFIX):
            self._callables.setdefault(variable.get_usr(), set()).add(
                callback)

    def bind_parameters(self, callee, arguments):
        """A package function's parameters hold what its callers pass.

        A helper that makes a subscription from its parameters
        (``TwistSubscriber(node, "cmd_vel", qos, callback)``) gets its
        topic as a string variable set by the callers (one literal in
        every call of the unit: that name) and its callback as a stored
        callable; the argument stays a plain reference of the caller.
        """
        definition = callee.get_definition() or callee
        params = [c for c in definition.get_children()
                  if c.kind == CK.PARM_DECL]
        for param, argument in zip(params, arguments):
            if not is_written(argument):
                continue
            if is_string(param):
                self.string_variables.assignment(param, argument)
                self.string_variables.passed(argument, param)
            elif is_callable_argument(argument):
                self.store_callable(param, argument, consume=False)

    def bind_arguments(self, callee, arguments, first_index=0,
                       caller=None):
        """Record what a call passes to a package function's parameters.

        Handles, and string literals (a node name passed to a base class).
        """
        for index, argument in enumerate(arguments, start=first_index):
            if caller is not None and is_string(argument):
                value, literal = written_name(argument)
                if literal:
                    fact_builder.add_string_argument(
                        self.facts, caller=caller, callee=callee, index=index,
                        value=value)
                    continue
            handle = plain_handle(argument)
            if handle is not None and self.places.in_package(handle):
                fact_builder.add_binding(
                    self.facts, callee=callee, index=index, handle=handle.get_usr())
            elif node_handle_marker(argument) is not None:
                # a handle made in place (getPrivateNodeHandle(),
                # ros::NodeHandle("~")): its namespace marker
                fact_builder.add_binding(
                    self.facts, callee=callee, index=index,
                    handle=node_handle_marker(argument))

    def _bound_arguments(self, argument):
        """Handles bound by boost::bind / std::bind to the callback."""
        for current in [argument] + list(walk_preorder(
                argument, stop=frozenset({CK.LAMBDA_EXPR}))):
            if current.kind != CK.CALL_EXPR or current.referenced is None or \
                    qualified_name(current.referenced) not in BIND_FUNCTIONS:
                continue
            bound = list(current.get_arguments())
            if not bound:
                return
            target = first_function(bound[0])
            if target is None or not self.places.in_package(target):
                return
            rest = bound[1:]
            # a bound method's first argument is the object, not a parameter
            if target.kind == CK.CXX_METHOD and not target.is_static_method():
                rest = rest[1:]
            self.bind_arguments(template_member(target).get_usr(), rest)
            return

    def resolve_callback(self, argument, consume=True):
        """Return (function id, declaration cursor) of a callback argument.

        With `consume`, the argument is registered with an API: it is a
        root of its own, not something the calling function calls.
        """
        if argument is None:
            return None, None
        self._bound_arguments(argument)
        for current in [argument] + list(walk_preorder(
                argument, stop=frozenset({CK.LAMBDA_EXPR}))):
            if current.kind == CK.LAMBDA_EXPR:
                lid = self.places.lambda_id(current)
                if consume:
                    self.consumed.add(self.places.key(current))
                    self.registered.add(lid)
                return lid, current
            if current.kind not in REF_KINDS:
                continue
            ref = current.referenced
            if ref is None:
                continue
            if ref.kind in FUNCTION_KINDS and self.places.in_package(ref):
                ref = template_member(ref)
                if consume:
                    self.consumed.add(self.places.key(current))
                    self.registered.add(ref.get_usr())
                return ref.get_usr(), ref
            if ref.kind == CK.VAR_DECL:
                for child in ref.get_children():
                    if child.kind == CK.LAMBDA_EXPR:
                        lid = self.places.lambda_id(child)
                        self.registered.add(lid)
                        return lid, child
            if ref.kind in HANDLE_KINDS and is_callable(ref) or \
                    ref.kind == CK.PARM_DECL and not _holds_no_callable(ref):
                # resolved at the end of the walk: see
                # resolve_stored_callbacks (a parameter: what the callers
                # pass, see bind_parameters)
                return CALLABLE_PREFIX + ref.get_usr(), None
        return None, None
