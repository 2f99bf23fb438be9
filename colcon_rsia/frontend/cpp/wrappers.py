# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Summaries of the workspace's wrapper functions, across packages.

The paper's per-function summaries, for the functions of other packages:
a library package of the workspace often makes endpoints for the others:
``make_publisher<M>(node, topic)``, a helper class whose constructor
creates a publisher that its methods publish through, a debug publisher
that creates one on first use. Their bodies are in headers the calling
unit includes, so the walk of a call site can read them: a wrapper is
summarised once per unit (which of its parameters is the topic, whether
its template argument is the message type, which parameter is the
callback, whether it publishes), and the call site gets the facts with
its own arguments.

Followed: publishers and subscriptions made from a parameter, a literal
or an expression; the message type as a concrete type or the wrapper's
template argument; callbacks passed as a parameter; publish calls in the
wrapper; endpoints stored in a member of a helper object and published
through by its other methods; wrappers calling wrappers (a few levels).

A wrapper defined in a ``.cpp`` of a library package is out of sight of
the units of other packages: its package exports the summary
(:meth:`Summaries.exported`, stored as ``wrappers.json``), and the
packages analysed after it (colcon's dependency order) read it back
(:class:`ExternalWrappers`) for the calls whose callee has no body here.
"""

from dataclasses import asdict
from dataclasses import dataclass
from typing import Optional

import clang.cindex as ci
from colcon_rsia.frontend import fact_builder
from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.cpp.const_eval import source_tokens
from colcon_rsia.frontend.cpp.cursors import call_arguments
from colcon_rsia.frontend.cpp.cursors import call_object
from colcon_rsia.frontend.cpp.cursors import callback_msg_type
from colcon_rsia.frontend.cpp.cursors import child_cursors
from colcon_rsia.frontend.cpp.cursors import explicit_template_type
from colcon_rsia.frontend.cpp.cursors import first_handle
from colcon_rsia.frontend.cpp.cursors import first_template_argument
from colcon_rsia.frontend.cpp.cursors import normalize_msg_type
from colcon_rsia.frontend.cpp.cursors import qualified_name
from colcon_rsia.frontend.cpp.cursors import role_argument
from colcon_rsia.frontend.cpp.cursors import walk_preorder
from colcon_rsia.frontend.cpp.questions import dependent_call_name
from colcon_rsia.frontend.cpp.questions import record_publish_site
from colcon_rsia.frontend.cpp.questions import stored_target
from colcon_rsia.frontend.cpp.strings import topic_source
from colcon_rsia.frontend.cpp.strings import written_name
from colcon_rsia.summary.wrapper_store import WrapperSummary

CK = ci.CursorKind

# wrappers calling wrappers: deeper chains are not followed
MAX_DEPTH = 3

ROLE_PUBLISHER = ros_api.PUBLISHER
ROLE_SUBSCRIBER = ros_api.SUBSCRIBER


@dataclass
class Endpoint:
    """One endpoint a wrapper makes, in terms of its parameters."""

    role: str                        # publisher | subscriber
    topic_param: Optional[int]       # the parameter that is the topic
    topic: Optional[str]             # else the topic as written inside
    topic_is_literal: bool
    msg_type: Optional[str]          # a concrete message type, or None:
    msg_type_from_call: bool         # the call's template argument
    callback_param: Optional[int]    # the parameter that is the callback
    member: Optional[str]            # the field it is stored in (USR)
    publishes: bool                  # the wrapper publishes through it


@dataclass
class Summary:
    """What calling one wrapper does."""

    endpoints: list
    # fields of the wrapper's class it publishes through (USRs)
    publishes_members: set


EMPTY = Summary([], set())


class ExternalWrappers:
    """The wrapper summaries other packages of the workspace exported."""

    def __init__(self, summaries=()):  # noqa: D107
        self._by_usr = {}
        by_name = {}
        for summary in summaries:
            try:
                converted = Summary(
                    [Endpoint(**e) for e in summary.endpoints],
                    set(summary.publishes_members))
            except TypeError:
                continue  # a file of another version: as if not analysed
            self._by_usr[summary.usr] = converted
            by_name.setdefault((summary.name, summary.arity), []).append(
                converted)
        # a parameter type that is a stand-in in one package and a model
        # class in another changes the USR: the name and arity still tell,
        # when they name one function only
        self._by_name = {k: v[0] for k, v in by_name.items() if len(v) == 1}

    def find(self, declaration):
        """The summary of a declared function with no body here, or EMPTY."""
        found = self._by_usr.get(declaration.get_usr())
        if found is None and self._by_name:
            arity = sum(1 for c in declaration.get_children()
                        if c.kind == CK.PARM_DECL)
            found = self._by_name.get((qualified_name(declaration), arity))
        return found or EMPTY


class Summaries:
    """Wrapper summaries of one unit, computed once per wrapper."""

    def __init__(  # noqa: D107
            self, facts, places, *, resolve_callback, problems,
            external=None):
        # the unit's facts, where cursors are (questions.Places), and
        # (function id, declaration) of a callback argument
        self.facts = facts
        self.places = places
        self.resolve_callback = resolve_callback
        # the unit's problems (one line each), appended to
        self.problems = problems
        self.external = external
        self._done = {}

    def of(self, declaration, depth=0):
        """The summary of the function a call refers to."""
        definition = _definition(declaration)
        if definition is None:
            return self.external.find(declaration) \
                if self.external is not None else EMPTY
        key = definition.get_usr() or str(definition.location)
        if key not in self._done:
            # a recursive wrapper meets its own (empty) summary
            self._done[key] = EMPTY
            if depth <= MAX_DEPTH:
                self._done[key] = self._summarise(definition, depth)
        return self._done[key]

    def exported(self, definitions):
        """Summaries of the unit's functions that make or publish endpoints.

        :param definitions: {function id: definition cursor} of the
          package's functions the walk met; those with endpoint facts or
          publish sites are summarised (``main`` is nobody's wrapper)
        """
        facts = self.facts
        candidates = {f.function for f in facts.publishers + facts.subscribers
                      + facts.publish_sites if f.function}
        result = []
        for function in sorted(candidates & set(definitions)):
            definition = definitions[function]
            if definition.spelling == 'main':
                continue
            try:
                summary = self.of(definition)
            except Exception as e:  # noqa: B902
                # what invalid code leaves may surprise the summary: the
                # function's callers lose its facts, the unit keeps its own
                self.problems.append(
                    f'{self.places.location(definition)}: '
                    f'{definition.spelling} not summarised for other '
                    f'packages (internal error: {type(e).__name__}: {e})')
                continue
            if not summary.endpoints and not summary.publishes_members:
                continue
            result.append(WrapperSummary(
                usr=function, name=qualified_name(definition),
                arity=sum(1 for c in definition.get_children()
                          if c.kind == CK.PARM_DECL),
                endpoints=[asdict(e) for e in summary.endpoints],
                publishes_members=sorted(summary.publishes_members)))
        return result

    def _summarise(self, definition, depth):
        params = {p.get_usr(): i for i, p in enumerate(
            c for c in definition.get_children() if c.kind == CK.PARM_DECL)}
        type_params = _template_parameters(definition)
        endpoints = []
        members = set()
        # a constructor's member initialisers run too
        pending = None
        initialised = {}
        for child in definition.get_children():
            if child.kind == CK.MEMBER_REF:
                pending = child.referenced
            elif pending is not None:
                initialised[_key(child)] = pending
                pending = None
        # and members the body assigns (`pub_ = node->create_publisher(…)`)
        for node in walk_preorder(definition):
            if node.kind == CK.CALL_EXPR and node.spelling == 'operator=':
                children = child_cursors(node)
                field = first_handle(children[0]) if len(children) > 1 \
                    else None
                if field is not None and field.kind == CK.FIELD_DECL:
                    initialised[_key(children[-1])] = field
        # the body and the initialisers alike
        nodes = [c for c in definition.get_children()
                 if c.kind not in (CK.PARM_DECL, CK.TYPE_REF,
                                   CK.NAMESPACE_REF, CK.TEMPLATE_REF)]
        for node in nodes:
            for call in [node] + list(walk_preorder(node)):
                if call.kind != CK.CALL_EXPR:
                    continue
                self._call(call, params, type_params, depth, endpoints,
                           members, initialised)
        return Summary(endpoints, members)

    def _call(self, call, params, type_params, depth, endpoints, members,
              initialised):
        ref = call.referenced
        name = qualified_name(ref) if ref is not None else None
        api = ros_api.lookup_call(name) if name else None
        if api is None and ref is None:
            name = dependent_call_name(call, ros2=self.places.ros2)
            api = ros_api.lookup_call(name) if name else None
        arguments = call_arguments(call)
        if api is not None and api.role in (ROLE_PUBLISHER, ROLE_SUBSCRIBER):
            endpoints.append(self._endpoint(
                call, api, arguments, params, type_params,
                _stored_in(call, initialised)))
            return
        if api is not None and api.role == ros_api.PUBLISH:
            handle = first_handle(call_object(call))
            if handle is not None and handle.kind == CK.FIELD_DECL:
                members.add(handle.get_usr())
            for endpoint in endpoints:
                # publishing through what it just made (a map of them too)
                if endpoint.member is None or handle is None or \
                        endpoint.member == handle.get_usr():
                    endpoint.publishes = True
            return
        if api is None and ref is not None and \
                self.places.is_workspace_declaration(ref):
            inner = self.of(ref, depth + 1)
            for endpoint in inner.endpoints:
                endpoints.append(self._through(
                    endpoint, call, arguments, params, type_params))

    def _through(self, endpoint, call, arguments, params, type_params):
        """An inner wrapper's endpoint, as this wrapper's call gives it.

        Its topic and callback parameters map to this wrapper's parameters
        where the call passes them on, else to what the call writes there;
        its message type comes from the call's template argument.
        """
        def argument(index):
            return arguments[index] \
                if index is not None and index < len(arguments) else None
        topic_param = _parameter_index(argument(endpoint.topic_param), params)
        topic, literal = endpoint.topic, endpoint.topic_is_literal
        if endpoint.topic_param is not None and topic_param is None:
            topic, literal = written_name(
                argument(endpoint.topic_param))
        msg_type, from_call = endpoint.msg_type, endpoint.msg_type_from_call
        if from_call:
            msg_type, from_call = _message_type(call, type_params)
        return Endpoint(
            role=endpoint.role, topic_param=topic_param, topic=topic,
            topic_is_literal=literal, msg_type=msg_type,
            msg_type_from_call=from_call,
            callback_param=_parameter_index(
                argument(endpoint.callback_param), params),
            member=None, publishes=endpoint.publishes)

    def _endpoint(self, call, api, arguments, params, type_params, member):
        topic_argument = role_argument(arguments, api.name_arg)
        topic_param = _parameter_index(topic_argument, params)
        topic, literal = (None, False) if topic_param is not None else \
            written_name(topic_argument)
        msg_type, from_call = _message_type(call, type_params)
        callback_param = None
        if api.callback_arg is not None:
            callback_param = _parameter_index(
                role_argument(arguments, api.callback_arg), params)
        return Endpoint(
            role=api.role, topic_param=topic_param, topic=topic,
            topic_is_literal=literal, msg_type=msg_type,
            msg_type_from_call=from_call, callback_param=callback_param,
            member=member.get_usr() if member is not None else None,
            publishes=False)

    def record_call(self, cursor, ctx, stack, ref):
        """A call of a workspace wrapper: the facts its summary gives.

        The call's own arguments fill the summary in. An endpoint the wrapper
        keeps in a member of a helper object is the handle
        ``<object>|<member>``, which the object's publishing methods
        publish through.
        """
        summary = self.of(ref)
        if not summary.endpoints and not summary.publishes_members:
            return
        arguments = call_arguments(cursor)
        target = stored_target(cursor, stack)
        obj = first_handle(call_object(cursor))
        name = qualified_name(ref)
        written = explicit_template_type(cursor) or \
            first_template_argument(cursor.type.get_canonical().spelling)
        location = self.places.location(cursor)
        # the helper object the wrapper's members belong to
        holder = target if ref.kind == CK.CONSTRUCTOR else obj

        def argument(index):
            return arguments[index] \
                if index is not None and index < len(arguments) else None
        for endpoint in summary.endpoints:
            # a topic the call passes that is no literal comes from where a
            # direct call's would: a constant, a parameter read, a variable
            topic_handle = affixes = None
            if endpoint.topic_param is not None:
                topic, literal = written_name(argument(endpoint.topic_param))
                if not literal:
                    topic_handle, affixes = topic_source(
                        argument(endpoint.topic_param))
            else:
                topic, literal = endpoint.topic, endpoint.topic_is_literal
            msg_type = endpoint.msg_type or (
                normalize_msg_type(written)
                if endpoint.msg_type_from_call else None)
            if endpoint.member is not None and holder is not None:
                handle = f'{holder.get_usr()}|{endpoint.member}'
            elif target is not None and endpoint.member is None:
                handle = target.get_usr()
            else:
                handle = f'wrapper@{location}'
            common = dict(
                function=ctx.function, api=name, topic=topic,
                topic_is_literal=literal, msg_type=msg_type, handle=handle,
                location=location, topic_handle=topic_handle,
                topic_affixes=affixes)
            if endpoint.role == ROLE_PUBLISHER:
                fact_builder.add_publisher(
                    self.facts, handle_name=target.spelling if target is not None
                    else None, **common)
            else:
                callback, declaration = self.resolve_callback(
                    argument(endpoint.callback_param))
                # a message type the wrapper deduces from the callback
                common['msg_type'] = common['msg_type'] or \
                    callback_msg_type(declaration)
                fact_builder.add_subscriber(
                    self.facts, callback=callback, **common)
            if endpoint.publishes:
                record_publish_site(self.facts, self.places.location, ctx,
                                    stack, cursor, name, handle)
        if obj is not None:
            for member in sorted(summary.publishes_members):
                record_publish_site(self.facts, self.places.location, ctx,
                                    stack, cursor, name,
                                    f'{obj.get_usr()}|{member}')


def _definition(declaration):
    """The definition of a function, also of a template's instantiation."""
    candidates = [declaration]
    # None for a function that is no template's instantiation
    template = ci.conf.lib.clang_getSpecializedCursorTemplate(declaration)
    if template is not None:
        candidates.append(template)
    for candidate in candidates:
        definition = candidate.get_definition()
        if definition is not None and any(
                c.kind == CK.COMPOUND_STMT for c in definition.get_children()):
            return definition
    return None


def _template_parameters(definition):
    """The names of the template type parameters of a function and class."""
    names = set()
    for scope in (definition, definition.semantic_parent):
        if scope is None:
            continue
        for child in scope.get_children():
            if child.kind == CK.TEMPLATE_TYPE_PARAMETER:
                names.add(child.spelling)
    return names


def _parameter_index(argument, params):
    """The wrapper parameter an argument is, as a whole, or None."""
    if argument is None:
        return None
    tokens = [t.spelling for t in source_tokens(argument)]
    # std::forward<CallbackT>(callback), std::move(topic): the parameter
    if len(tokens) > 1 and tokens[0] == 'std' and tokens[-1] == ')':
        tokens = tokens[tokens.index('(') + 1:-1] if '(' in tokens else tokens
    for current in [argument] + list(walk_preorder(argument)):
        if current.kind == CK.DECL_REF_EXPR and current.referenced is not None \
                and current.referenced.get_usr() in params and \
                tokens == [current.spelling]:
            return params[current.referenced.get_usr()]
    return None


def _message_type(call, type_params):
    """(message type, from the wrapper's own template argument) of a call.

    ``create_publisher<T>`` in ``template <class T>``: the wrapper's
    caller gives it; ``create_publisher<std_msgs::msg::String>``: that.
    """
    written = explicit_template_type(call) or \
        _written_template_argument(call)
    if written and written.split('::')[-1] in type_params:
        return None, True
    return (normalize_msg_type(written) if written else None), False


def _written_template_argument(call):
    """``T`` of ``node->template create_publisher<T>(...)`` as written."""
    children = list(call.get_children())
    if not children:
        return None
    tokens = [t.spelling for t in source_tokens(children[0])]
    if '<' not in tokens:
        return None
    depth = 0
    written = []
    for token in tokens[tokens.index('<'):]:
        depth += token.count('<') - token.count('>')
        if depth <= 0:
            break
        written.append(token)
    return ''.join(written[1:]) or None


def _key(cursor):
    return (cursor.extent.start.offset, cursor.extent.end.offset)


def _stored_in(call, initialised):
    """The member a constructor's initialiser stores the call's result in."""
    for key, member in initialised.items():
        start, end = key
        if start <= call.extent.start.offset and \
                call.extent.end.offset <= end:
            return member
    return None
