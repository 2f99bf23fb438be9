# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The facts of one node: the functions it runs and what they do.

An executable runs every function of its own translation units and whatever
they call in the package's libraries; a nodelet runs the methods of its
class and whatever they call. Facts of all the node's TUs are merged (by
function id, which is stable across TUs) before labelling.
"""

from dataclasses import asdict
from dataclasses import dataclass
from dataclasses import field
from dataclasses import replace
from typing import Dict
from typing import List
from typing import Optional

from colcon_rsia.frontend import ros_api
from colcon_rsia.frontend.facts import ActionFact
from colcon_rsia.frontend.facts import Call
from colcon_rsia.frontend.facts import ClientFact
from colcon_rsia.frontend.facts import Function
from colcon_rsia.frontend.facts import HostEvent
from colcon_rsia.frontend.facts import NodeletLoad
from colcon_rsia.frontend.facts import NodeNameFact
from colcon_rsia.frontend.facts import PacedLoop
from colcon_rsia.frontend.facts import ParamRead
from colcon_rsia.frontend.facts import PublisherFact
from colcon_rsia.frontend.facts import PublishSite
from colcon_rsia.frontend.facts import RateObject
from colcon_rsia.frontend.facts import Registration
from colcon_rsia.frontend.facts import RETURNED_HANDLE
from colcon_rsia.frontend.facts import ServiceFact
from colcon_rsia.frontend.facts import SubscriberFact
from colcon_rsia.frontend.facts import SyncFact
from colcon_rsia.frontend.facts import TimerFact
from colcon_rsia.frontend.facts import TuFacts
from colcon_rsia.summary.kinds import UNKNOWN_NAMESPACE
from colcon_rsia.summary.nodes import TopicParam


@dataclass
class NodeFacts:
    """Facts restricted to the functions one node runs."""

    functions: Dict[str, Function] = field(default_factory=dict)
    calls: List[Call] = field(default_factory=list)
    publishers: List[PublisherFact] = field(default_factory=list)
    subscribers: List[SubscriberFact] = field(default_factory=list)
    timers: List[TimerFact] = field(default_factory=list)
    services: List[ServiceFact] = field(default_factory=list)
    actions: List[ActionFact] = field(default_factory=list)
    publish_sites: List[PublishSite] = field(default_factory=list)
    paced_loops: List[PacedLoop] = field(default_factory=list)
    registrations: List[Registration] = field(default_factory=list)
    host_events: List[HostEvent] = field(default_factory=list)
    nodelet_loads: List[NodeletLoad] = field(default_factory=list)
    rates: Dict[str, RateObject] = field(default_factory=dict)
    syncs: List[SyncFact] = field(default_factory=list)
    node_names: List[NodeNameFact] = field(default_factory=list)
    # parameter USR -> the string literals the node's calls pass to it
    string_arguments: Dict[str, set] = field(default_factory=dict)
    clients: List[ClientFact] = field(default_factory=list)
    namespaces: Dict[str, str] = field(default_factory=dict)
    # handle USR -> the handles it may stand for (parameters bound by
    # calls and binds)
    aliases: Dict[str, set] = field(default_factory=dict)
    # variable USR -> the parameter read into it
    param_reads: Dict[str, ParamRead] = field(default_factory=dict)
    # parameter name -> its default where the node declares/reads it with one
    param_defaults: Dict[str, str] = field(default_factory=dict)
    # a plugin: its host (colcon_rsia.package.plugin_hosts.Host) and the
    # root kind the host gives each method it calls, {function id: kind}
    host: Optional[object] = None
    host_roots: Dict[str, str] = field(default_factory=dict)


def _most_resolved(endpoints):
    """Each call site as resolved as one of the units saw it.

    A helper in a header (a subscription made from its parameters) is
    walked by every unit that includes it; those that also see its callers
    resolve the topic and callback they pass, the others keep the
    parameter's name: those copies go where a resolved one exists.
    """
    sites = {}
    for endpoint in endpoints:
        sites.setdefault(
            (endpoint.function, endpoint.location, endpoint.api), []).append(
                endpoint)
    kept = []
    for endpoint in endpoints:
        others = sites[(endpoint.function, endpoint.location, endpoint.api)]
        if not endpoint.topic_is_literal and \
                any(o.topic_is_literal for o in others):
            continue
        if getattr(endpoint, 'callback', True) is None and any(
                o.callback for o in others if o.topic == endpoint.topic):
            continue
        kept.append(endpoint)
    return kept


def unique(items):
    """Drop repeated facts (a header's functions appear in every TU)."""
    seen = set()
    result = []
    for item in items:
        key = repr(asdict(item))
        if key not in seen:
            seen.add(key)
            result.append(item)
    return result


def merge_facts(units):
    """Merge the facts of several translation units into one.

    A call of a virtual method also calls every override of it in the
    package's classes derived from the method's class (which one runs is
    the object's dynamic type).
    """
    merged = TuFacts(source='')
    for unit in units:
        merged.extend(unit)
    _link_by_name(merged)
    merged.calls += _override_calls(merged)
    return merged


def _usr_name(usr):
    """The part of a function's USR that names it, before its signature."""
    name, hash_, _ = usr.partition('#')
    return name if hash_ and '@F@' in name else None


def _link_by_name(facts):
    """Calls of a function declared in one unit and defined in another.

    A function's id (its USR) spells its parameters' types. In a unit
    where the model mode left a parameter's type undeclared (no repair
    paid there), the declaration's id differs from that of the
    definition another unit repaired, and the call reached nothing. The
    linker's rule without the types: a called function no unit defines is
    the one definition of the same qualified name, when there is one.
    """
    defined = {f.id for f in facts.functions}
    by_name = {}
    for function in facts.functions:
        name = _usr_name(function.id)
        if name is not None:
            by_name.setdefault(name, set()).add(function.id)

    def linked(callee):
        if callee in defined:
            return callee
        found = by_name.get(_usr_name(callee) or '', ())
        return next(iter(found)) if len(found) == 1 else callee
    facts.calls = [c if linked(c.callee) == c.callee
                   else replace(c, callee=linked(c.callee))
                   for c in facts.calls]
    facts.bindings = [b if linked(b.callee) == b.callee
                      else replace(b, callee=linked(b.callee))
                      for b in facts.bindings]
    facts.string_arguments = [
        a if linked(a.callee) == a.callee
        else replace(a, callee=linked(a.callee))
        for a in facts.string_arguments]


def _override_calls(facts):
    """Calls of the overrides of the virtual methods the calls name.

    Each keeps its call's ``on_this``; being no call as written
    (``virtual`` None), it is an override the object's own class may not
    have: select_functions keeps only those of a node's class hierarchy.
    """
    virtual = [c for c in facts.calls if c.virtual]
    if not virtual:
        return []
    derived = {}
    for name, base in facts.class_bases:
        derived.setdefault(base, set()).add(name)
    by_name = {}
    for function in facts.functions:
        by_name.setdefault(function.name, []).append(function.id)
    calls = []
    for call in virtual:
        owner, _, method = call.virtual.rpartition('::')
        # the classes derived from the method's class, at any depth
        found, todo = set(), list(derived.get(owner, ()))
        while todo:
            current = todo.pop()
            if current not in found:
                found.add(current)
                todo.extend(derived.get(current, ()))
        for name in sorted(found):
            calls += [replace(call, callee=override, virtual=None)
                      for override in by_name.get(f'{name}::{method}', ())
                      if override != call.callee]
    return calls


def _callbacks_registered_by(facts):
    """{function id: [callback ids it registers]}."""
    registered = {}

    def add(function, callbacks):
        for callback in callbacks:
            if function and callback:
                registered.setdefault(function, []).append(callback)
    for fact in facts.subscribers:
        add(fact.function, [fact.callback])
    for fact in facts.publishers:
        add(fact.function, fact.status_callbacks)
    for fact in facts.timers + facts.services:
        add(fact.function, [fact.callback])
    for fact in facts.actions:
        add(fact.function, fact.callbacks)
    for fact in facts.registrations + facts.host_events:
        add(fact.function, [fact.callback])
    return registered


def select_functions(facts, seeds, hierarchy=None):
    """All functions reachable from `seeds` by calls and registrations.

    :param hierarchy: the node's class and its bases, when the node is an
      object of one class (a plugin): a virtual call it makes on itself
      runs that class's override, never a sibling class's
    """
    owners = {f.id: f.name.rpartition('::')[0] for f in facts.functions} \
        if hierarchy is not None else {}
    edges = {}
    for call in facts.calls:
        if hierarchy is not None and call.on_this and \
                call.virtual is None and \
                owners.get(call.callee) not in hierarchy:
            continue  # (an override of another class: see _override_calls)
        edges.setdefault(call.caller, []).append(call.callee)
    for function, callbacks in _callbacks_registered_by(facts).items():
        edges.setdefault(function, []).extend(callbacks)
    selected = set()
    todo = list(seeds)
    while todo:
        current = todo.pop()
        if current in selected:
            continue
        selected.add(current)
        todo.extend(edges.get(current, ()))
    return selected


def node_facts(facts, function_ids, library_files=frozenset()):
    """Restrict merged package facts to the functions of one node.

    :param library_files: the sources of the package's library the node
      links (``file`` as in locations): an endpoint one of their functions
      makes per call is placed at the node's call (see _made_per_call)
    """
    functions = {}
    for function in facts.functions:
        if function.id in function_ids:
            functions.setdefault(function.id, function)
    classes = {f.class_id for f in functions.values() if f.class_id}

    def owned(fact):
        if fact.function is not None:
            return fact.function in functions
        return getattr(fact, 'class_id', None) in classes

    result = NodeFacts(functions=functions)
    result.calls = unique(
        c for c in facts.calls if c.caller in functions)
    result.publishers = _most_resolved(
        unique(p for p in facts.publishers if owned(p)))
    result.subscribers = _most_resolved(
        unique(s for s in facts.subscribers if owned(s)))
    result.timers = unique(t for t in facts.timers if owned(t))
    result.services = unique(s for s in facts.services if owned(s))
    result.actions = unique(a for a in facts.actions if owned(a))
    result.publish_sites = unique(
        s for s in facts.publish_sites if s.function in functions)
    result.paced_loops = unique(
        p for p in facts.paced_loops if p.function in functions)
    result.registrations = unique(
        r for r in facts.registrations if r.function in functions)
    result.host_events = unique(
        e for e in facts.host_events if e.function in functions)
    result.nodelet_loads = unique(
        n for n in facts.nodelet_loads if n.function in functions)
    result.node_names = unique(
        n for n in facts.node_names if n.function in functions)
    for argument in facts.string_arguments:
        callee = functions.get(argument.callee)
        if argument.caller in functions and callee is not None and \
                argument.index < len(callee.params):
            result.string_arguments.setdefault(
                callee.params[argument.index], set()).add(argument.value)
    result.publishers = _named_by_callers(
        _made_per_call(result.publishers, result, library_files), result)
    result.subscribers = _named_by_callers(
        _made_per_call(result.subscribers, result, library_files), result)
    result.clients = unique(c for c in facts.clients if owned(c))
    result.rates = {r.handle: r for r in facts.rates}
    result.syncs = unique(facts.syncs)
    result.namespaces = {h.handle: h.namespace for h in facts.node_handles}
    result.aliases = _parameter_aliases(functions, facts.bindings)
    for alias in facts.handle_aliases:
        result.aliases.setdefault(alias.alias, set()).update(
            handles_of(result, alias.handle))
    reads = [r for r in facts.param_reads if r.function in functions]
    result.param_reads = {r.handle: r for r in reads if r.handle}
    result.param_defaults = {
        r.name: r.default for r in reads if r.default is not None}
    _attach_filter_callbacks(result)
    return result


def _made_per_call(endpoints, facts, library_files=frozenset()):
    """One endpoint per call of a function that makes it of its parameter.

    ``SubscribeWithHandler<M>(handler, id, topic, nh, node)`` subscribes to
    its parameter ``topic``: each call the node makes subscribes to what
    that call passes (``kImuTopic``, ``kOdometryTopic``), as the calls of
    another package's wrapper do (frontend/cpp/wrappers.py). A call that
    passes nothing that can name a topic (a message's field) makes one as
    written: never the name another call passes.

    The copies keep the place the function makes the endpoint, but for a
    function of the package's library (`library_files`) called from the
    node's own code: that library is linked as another package's would be,
    and its endpoint is placed, as a wrapper's is, at the call, with the
    place it is made in ``made_in``.
    """
    made = []
    for endpoint in endpoints:
        index = endpoint.topic_argument
        calls = [] if index is None else [
            c for c in facts.calls
            if c.callee == endpoint.function and c.kind == 'call']
        passed = [next((a for a in c.name_arguments if a.index == index),
                       None) for c in calls]
        if not calls or (None in passed and endpoint.topic_is_literal):
            # (a name the unit resolved: every call it saw passed it)
            made.append(endpoint)
            continue
        for call, argument in zip(calls, passed):
            copy = _passed_topic(endpoint, argument) \
                if argument is not None else replace(
                    endpoint, topic_handle=None, topic_affixes=None,
                    topic_argument=None)
            if _file_of(endpoint.location) in library_files and \
                    _file_of(call.location) not in library_files:
                copy = replace(copy, location=call.location,
                               made_in=endpoint.location)
            made.append(copy)
    return unique(made)


def _file_of(location):
    return location.rpartition(':')[0]


def _passed_topic(endpoint, argument):
    """The endpoint, of the topic one call passes (a NameArgument)."""
    prefix, suffix = endpoint.topic_affixes or ('', '')
    if argument.topic_is_literal and \
            ros_api.joins_after_node_name(argument.topic, suffix):
        return replace(
            endpoint, topic=prefix + argument.topic + suffix,
            topic_is_literal=True, topic_handle=None, topic_affixes=None,
            topic_argument=None)
    if argument.topic_is_literal or (
            endpoint.topic_affixes and argument.topic_affixes):
        # (the code joins what the caller passes: left as written)
        return replace(endpoint, topic_argument=None)
    return replace(
        endpoint, topic=argument.topic, topic_is_literal=False,
        topic_handle=argument.topic_handle,
        topic_affixes=argument.topic_affixes or endpoint.topic_affixes,
        topic_argument=None)


def _named_by_callers(endpoints, facts):
    """Endpoints whose topic is a parameter the node's callers give.

    ``BatteryState(node, const std::string & topic)`` creating a publisher
    of `topic`, constructed in another unit as ``BatteryState(node,
    "battery_state")``: when every call the node makes passes one literal,
    that is the name (a copy of the fact: another node may pass another).
    """
    named = []
    for endpoint in endpoints:
        values = facts.string_arguments.get(endpoint.topic_handle) \
            if not endpoint.topic_is_literal and endpoint.topic_handle \
            else None
        prefix, suffix = endpoint.topic_affixes or ('', '')
        if values is not None and len(values) == 1 and \
                ros_api.joins_after_node_name(next(iter(values)), suffix):
            # (joined with what the code adds: `name + "/goal"`)
            endpoint = replace(
                endpoint, topic=prefix + next(iter(values)) + suffix,
                topic_is_literal=True, topic_handle=None, topic_affixes=None)
        named.append(endpoint)
    return named


def _parameter_aliases(functions, bindings):
    """{parameter USR: handles passed to it}, through chains of calls."""
    bound = {}
    for binding in bindings:
        function = functions.get(binding.callee)
        if function is None or binding.index >= len(function.params):
            continue
        bound.setdefault(function.params[binding.index], set()).add(
            binding.handle)
    aliases = {}
    for param in bound:
        seen = set()
        todo = [param]
        while todo:
            current = todo.pop()
            for handle in bound.get(current, ()):
                if handle not in seen:
                    seen.add(handle)
                    todo.append(handle)
        aliases[param] = seen
    return aliases


def topic_param(facts, fact):
    """The parameter a non-literal topic comes from, or None.

    The topic is a variable a parameter was read into, or (marked
    ``param:<name>``) a parameter read in place; the default may come
    from another read of the same parameter (ROS 2 declares a parameter
    with its default and gets it elsewhere).
    """
    marker = fact.topic_handle or ''
    if marker.startswith('param:'):
        name, default, namespace = marker[len('param:'):], None, '~'
    else:
        read = facts.param_reads.get(marker) if marker else None
        if read is None:
            read = _read_passed(facts, marker)
        if read is None:
            return None
        name, default = read.name, read.default
        namespace = resolve_namespace(facts, read.nh)
    if default is None:
        default = facts.param_defaults.get(name)
    prefix, suffix = getattr(fact, 'topic_affixes', None) or ('', '')
    return TopicParam(name=name, default=default, namespace=namespace,
                      prefix=prefix, suffix=suffix)


def _read_passed(facts, parameter):
    """The parameter read whose variable every caller passes, or None.

    ``Saver(node, map_name_)`` where ``map_name_ = declare_parameter(
    "map_name", ...)`` and the saver's topic is its ``map_name``
    parameter (held in a member set only to it, frontend/cpp/strings.py).
    """
    if not parameter or facts.string_arguments.get(parameter):
        return None
    passed = facts.aliases.get(parameter, set())
    # (a parameter passing on its own callers' values is no value itself)
    values = {h for h in passed if h not in facts.aliases}
    if len(values) != 1:
        return None
    return facts.param_reads.get(next(iter(values)))


def handles_of(facts, handle):
    """The handle itself and every handle a parameter may stand for."""
    return {handle} | facts.aliases.get(handle, set())


def _attach_filter_callbacks(facts):
    """message_filters subscribers get the callbacks registered on them.

    The callback is registered on the subscriber itself or on a
    synchronizer that takes the subscriber as one of its inputs.
    """
    by_handle = {}
    for registration in facts.registrations:
        if registration.handle and registration.callback:
            by_handle.setdefault(registration.handle, []).append(
                registration.callback)
    for sync in facts.syncs:
        for callback in by_handle.get(sync.handle, []):
            for handle in sync.inputs:
                by_handle.setdefault(handle, []).append(callback)
    # copies: the same fact object may belong to several nodes
    facts.subscribers = [
        replace(s, callback=sorted(by_handle[s.handle])[0])
        if s.callback is None and s.handle in by_handle else s
        for s in facts.subscribers]


def resolve_namespace(facts, marker, depth=0):
    """The namespace a NodeHandle marker stands for ('' when unknown).

    A marker is '' (node namespace), '~' (private), a namespace as
    written, the USR of a NodeHandle variable, 'ref:<usr>|<sub>', or
    'ret:<function usr>', the handle a function returns.
    """
    # a handle may be built from another; a short chain is enough
    if marker is None or depth > 8:
        return ''
    if marker.startswith('ref:'):
        parent, _, sub = marker[4:].partition('|')
        base = resolve_namespace(facts, parent, depth + 1)
        if not sub:
            return base
        if sub.startswith(('/', UNKNOWN_NAMESPACE)) or not base:
            return sub
        if base.startswith(UNKNOWN_NAMESPACE):
            return base
        return f'{base}/{sub}'
    # a NodeHandle parameter: the handles the callers pass, when they agree
    passed = {resolve_namespace(facts, handle, depth + 1)
              for handle in facts.aliases.get(marker, ())}
    if len(passed) == 1:
        return passed.pop()
    if marker in facts.namespaces:
        return resolve_namespace(facts, facts.namespaces[marker], depth + 1)
    if marker.startswith(RETURNED_HANDLE):
        # a function whose body is not seen, or returning several handles
        name = marker.rpartition('@F@')[2].partition('#')[0]
        return f'{UNKNOWN_NAMESPACE}{name}()'
    if marker.startswith('c:'):
        return ''  # a handle whose construction we did not see
    return marker
