# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Algorithm 1 of the paper: label each publisher of a node.

A publisher edge is *independent* of the node's incoming rates when

1. the node has no inputs at all (no subscriber, tf listener, service or
   action server): ``no_subscribers``; or
2. every call path from a root to each of its publish sites starts at a
   timer callback (``timer``) or passes through a loop paced by the
   ``sleep()`` of a Rate object (``rate_loop``); both kinds: ``mixed``.
   A plugin's method that its host calls from a fixed-rate loop (a
   controller's ``update()``) is paced like a timer callback:
   ``host_periodic``.

Otherwise it is *dependent* (``none``). Enumerating every loop-free path is
exponential; a path is bad exactly when it starts at a non-timer root and
uses no paced call edge, so "some bad path exists" is a reachability
question over the unpaced edges from the non-timer roots (a walk using only
unpaced edges contains a loop-free path using a subset of them).
"""

from colcon_rsia.frontend import python_api
from colcon_rsia.frontend import ros_api
from colcon_rsia.package.node_facts import handles_of
from colcon_rsia.package.node_facts import resolve_namespace
from colcon_rsia.package.node_facts import topic_param
from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.kinds import ORIGIN_TOKENS
from colcon_rsia.summary.kinds import PATTERN_HOST_PERIODIC
from colcon_rsia.summary.kinds import PATTERN_MIXED
from colcon_rsia.summary.kinds import PATTERN_NO_SUBSCRIBERS
from colcon_rsia.summary.kinds import PATTERN_NONE
from colcon_rsia.summary.kinds import PATTERN_RATE_LOOP
from colcon_rsia.summary.kinds import PATTERN_TIMER
from colcon_rsia.summary.kinds import ROOT_ACTION
from colcon_rsia.summary.kinds import ROOT_CONNECT
from colcon_rsia.summary.kinds import ROOT_ENTRY
from colcon_rsia.summary.kinds import ROOT_HOST_PERIODIC
from colcon_rsia.summary.kinds import ROOT_HOST_REQUEST
from colcon_rsia.summary.kinds import ROOT_MAIN
from colcon_rsia.summary.kinds import ROOT_NODELET
from colcon_rsia.summary.kinds import ROOT_SERVICE
from colcon_rsia.summary.kinds import ROOT_SUBSCRIBER
from colcon_rsia.summary.kinds import ROOT_TIMER
from colcon_rsia.summary.kinds import TRIGGER_ALL
from colcon_rsia.summary.nodes import Evidence
from colcon_rsia.summary.nodes import LabelledPublisher
from colcon_rsia.summary.nodes import Root
from colcon_rsia.summary.nodes import Trigger


def find_roots(facts):
    """Return {function id: (kind, location)} of a node's roots."""
    roots = {}

    def add(function, kind, location):
        if function and function in facts.functions:
            # a paced root stays one only if nothing else (a subscription,
            # a service) also calls it from outside
            previous = roots.get(function)
            if previous is None or previous[0] in PACED_ROOTS:
                roots[function] = (kind, location)
    for function, kind in sorted(facts.host_roots.items()):
        if function in facts.functions:
            add(function, kind, facts.functions[function].location)
    for function in facts.functions.values():
        if function.name == ros_api.MAIN_FUNCTION:
            add(function.id, ROOT_MAIN, function.location)
        elif function.name.endswith('::' + ros_api.NODELET_INIT_METHOD):
            add(function.id, ROOT_NODELET, function.location)
    for timer in facts.timers:
        add(timer.callback, ROOT_TIMER, timer.location)
    for subscriber in facts.subscribers:
        add(subscriber.callback, ROOT_SUBSCRIBER, subscriber.location)
    for publisher in facts.publishers:
        for callback in publisher.status_callbacks:
            add(callback, ROOT_CONNECT, publisher.location)
    for service in facts.services:
        add(service.callback, ROOT_SERVICE, service.location)
    for action in facts.actions:
        for callback in action.callbacks:
            add(callback, ROOT_ACTION, action.location)
    for registration in facts.registrations:
        add(registration.callback, ROOT_SUBSCRIBER,
            registration.location)
    called = {c.callee for c in facts.calls if c.caller in facts.functions}
    for function in facts.functions.values():
        if function.id not in roots and function.id not in called:
            add(function.id, ROOT_ENTRY, function.location)
    # functions reachable from no root (a cycle nobody enters) are entered
    # from outside as far as we can tell
    reached = _reach(roots, _edges(facts.calls))
    for function in facts.functions.values():
        if function.id not in reached:
            roots[function.id] = (ROOT_ENTRY, function.location)
            reached |= _reach([function.id], _edges(facts.calls))
    return roots


# roots whose calls come at a rate of their own, not with the node's inputs
PACED_ROOTS = (ROOT_TIMER, ROOT_HOST_PERIODIC)


def _edges(calls, keep=None):
    edges = {}
    for call in calls:
        if keep is None or keep(call):
            edges.setdefault(call.caller, []).append(call)
    return edges


def _reach(starts, edges, parents=None):
    reached = set()
    todo = list(starts)
    while todo:
        current = todo.pop()
        if current in reached:
            continue
        reached.add(current)
        for call in edges.get(current, ()):
            if call.callee not in reached:
                if parents is not None:
                    parents.setdefault(call.callee, call)
                todo.append(call.callee)
    return reached


def has_inputs(facts):
    """Whether anything outside drives the node (pattern 1 fails)."""
    return bool(facts.subscribers or facts.services or any(
        a.role == 'server' for a in facts.actions) or any(
        kind == ROOT_HOST_REQUEST for kind in facts.host_roots.values()))


def label_publishers(facts):
    """Label every publisher of one node (see the module docstring).

    :param facts: the node's :class:`colcon_rsia.package.node_facts.NodeFacts`
    :returns: the labelled publishers and the roots
    """
    roots = find_roots(facts)
    paced = {p.loop: p for p in facts.paced_loops}

    def is_paced(loops):
        return [paced[loop] for loop in loops if loop in paced]

    all_edges = _edges(facts.calls)
    timer_roots = [f for f, (k, _) in roots.items()
                   if k == ROOT_TIMER]
    host_roots = [f for f, (k, _) in roots.items()
                  if k == ROOT_HOST_PERIODIC]
    other_roots = [f for f, (k, _) in roots.items()
                   if k not in PACED_ROOTS]
    bad_parents = {}
    unpaced_from_others = _reach(
        other_roots, _edges(facts.calls, lambda c: not is_paced(c.loops)),
        bad_parents)
    from_timers = _reach(timer_roots, all_edges)
    from_host = _HostReach(facts, host_roots, all_edges)
    from_others = _reach(other_roots, all_edges)
    callers_of = {}
    for call in facts.calls:
        callers_of.setdefault(call.callee, []).append(call)

    driven = has_inputs(facts)
    triggers = _TriggerWalk(facts, roots, is_paced)
    labelled = []
    for publisher in facts.publishers:
        sites = [s for s in facts.publish_sites
                 if publisher.handle and s.handle and
                 publisher.handle in handles_of(facts, s.handle)]
        evidence = [Evidence(
            'publish_site', s.location,
            s.api + (' (read from tokens)' if s.origin == ORIGIN_TOKENS else ''))
                    for s in sites]
        base = dict(
            topic=publisher.topic, topic_is_literal=publisher.topic_is_literal,
            msg_type=publisher.msg_type, api=publisher.api,
            handle=publisher.handle_name,
            namespace=resolve_namespace(facts, publisher.nh),
            location=publisher.location,
            publish_sites=sorted({s.location for s in sites}),
            topic_param=topic_param(facts, publisher),
            origin=publisher.origin, made_in=publisher.made_in)
        if not driven:
            evidence.append(Evidence(
                'no_subscribers', publisher.location,
                'the node has no subscriber, service or action server'))
            # its own pacing still sets its rate (`colcon rsia rates`)
            paced = _paced_rate(sites, *_label_sites(
                sites, facts, roots, is_paced, unpaced_from_others,
                bad_parents, from_timers, from_host, from_others, callers_of,
                []))
            # the rate is its pacing's (a talker's `ros::Rate loop(10)`)
            labelled.append(LabelledPublisher(
                label=INDEPENDENT,
                pattern=PATTERN_NO_SUBSCRIBERS,
                rate_hz=paced.get('paced_rate_hz'),
                evidence=evidence, **base, **paced))
            continue
        if not sites:
            evidence.append(Evidence(
                'no_publish_site', publisher.location,
                'no publish call through this publisher was found'))
            labelled.append(LabelledPublisher(
                label=DEPENDENT, pattern=PATTERN_NONE,
                rate_hz=None, evidence=evidence,
                triggers=[triggers.all_inputs(
                    publisher.location,
                    'no publish call through this publisher was found')],
                **base))
            continue
        label, pattern, rates = _label_sites(
            sites, facts, roots, is_paced, unpaced_from_others, bad_parents,
            from_timers, from_host, from_others, callers_of, evidence)
        rate_hz = None
        if label == INDEPENDENT and len(rates) == 1:
            rate_hz = next(iter(rates))
        labelled.append(LabelledPublisher(
            label=label, pattern=pattern, rate_hz=rate_hz,
            evidence=evidence,
            triggers=triggers.of(sites) if label == DEPENDENT
            else None, **base, **_paced_rate(sites, label, pattern, rates)))
    root_list = [Root(facts.functions[f].name, kind, location)
                 for f, (kind, location) in roots.items()]
    return labelled, sorted(root_list, key=lambda r: (r.location, r.function))


def _label_sites(sites, facts, roots, is_paced, unpaced_from_others,
                 bad_parents, from_timers, from_host, from_others, callers_of,
                 evidence):
    kinds = set()
    rates = set()
    for site in sites:
        site_loops = is_paced(site.loops)
        if not site_loops and site.function in unpaced_from_others:
            evidence.append(_bad_path(site, facts, roots, bad_parents))
            return DEPENDENT, PATTERN_NONE, set()
        if site.function in from_timers:
            kinds.add(PATTERN_TIMER)
            for timer in facts.timers:
                if timer.callback and _reaches(
                        timer.callback, site.function, facts):
                    rates.add(timer.rate_hz)
                    evidence.append(Evidence(
                        'timer', timer.location, _timer_detail(timer, facts)))
        if site.function in from_host.reached:
            kinds.add(PATTERN_HOST_PERIODIC)
            # the host's loop rate is its own parameter, not in the code
            rates.add(None)
            evidence.append(from_host.evidence(site.function))
        if site.function in from_others or site_loops:
            kinds.add(PATTERN_RATE_LOOP)
            loops = site_loops + _paced_calls_into(
                site.function, facts, is_paced, callers_of)
            for loop in loops:
                rate = facts.rates.get(loop.rate_handle)
                rates.add(rate.rate_hz if rate is not None else None)
                evidence.append(Evidence(
                    'rate_loop', loop.location,
                    f'paced by sleep() at {loop.sleep_location}'))
    pattern = kinds.pop() if len(kinds) == 1 else PATTERN_MIXED
    return INDEPENDENT, pattern, rates


class _HostReach:
    """What a plugin's periodic host calls reach, and why."""

    def __init__(self, facts, starts, edges):
        self.facts = facts
        # each periodic method's reach, walked once
        self.by_start = {start: _reach([start], edges)
                         for start in sorted(starts)}
        self.reached = set().union(*self.by_start.values())

    def evidence(self, function):
        """Evidence naming the host call that reaches `function`.

        :param function: one of ``self.reached``
        """
        host = self.facts.host
        start = next(s for s, reached in self.by_start.items()
                     if function in reached)
        method = self.facts.functions[start]
        return Evidence(
            'host_periodic', method.location,
            f'{host.host} calls {method.name} from its fixed-rate loop '
            f'({host.rate_parameter})')


def _reaches(start, target, facts):
    return target in _reach([start], _edges(facts.calls))


def _paced_calls_into(function, facts, is_paced, callers_of):
    """The paced loops whose calls lead (transitively) to `function`."""
    loops = []
    seen = set()
    todo = [function]
    while todo:
        current = todo.pop()
        if current in seen:
            continue
        seen.add(current)
        for call in callers_of.get(current, ()):
            found = is_paced(call.loops)
            if found:
                loops.extend(found)
            else:
                todo.append(call.caller)
    return loops


def _timer_detail(timer, facts):
    callback = facts.functions.get(timer.callback)
    name = callback.name if callback else timer.callback
    rate = f' at {timer.rate_hz:g} Hz' if timer.rate_hz else ''
    return f'timer callback {name}{rate}'


def _bad_path(site, facts, roots, parents):
    """Evidence for a dependent site: one path that decides it."""
    path = [site.location]
    current = site.function
    seen = set()
    while current in parents and current not in roots and current not in seen:
        seen.add(current)
        call = parents[current]
        path.append(call.location)
        current = call.caller
    kind, location = roots.get(current, (ROOT_ENTRY, '?'))
    function = facts.functions.get(current)
    name = function.name if function else current
    return Evidence(
        'path', location,
        f'{kind} root {name} reaches the publish site without a timer or '
        f'a rate loop (via {" <- ".join(path)})')


def _paced_rate(sites, label, pattern, rates):
    """The ``paced_rate_hz``/``paced_by`` fields of a publisher."""
    if not sites or label != INDEPENDENT or len(rates) != 1 or \
            pattern == PATTERN_MIXED:
        return {}
    rate = next(iter(rates))
    return {'paced_rate_hz': rate, 'paced_by': pattern} if rate else {}


class _TriggerWalk:
    """Which inputs of a node drive each dependent publisher.

    The walk is Algorithm 1's: unpaced call edges, one start at a time.
    An input whose callback reaches a publish site along it triggers the
    publisher; a root that is no input's callback (``main``, a nodelet's
    ``onInit``, a function nobody calls) reaching it along it, or an input
    whose callback cannot be followed, leaves every input as a trigger.
    """

    def __init__(self, facts, roots, is_paced):
        self.facts = facts
        self.roots = roots
        self.unpaced = _edges(facts.calls, lambda c: not is_paced(c.loops))
        self.is_paced = is_paced
        self.inputs = _inputs(facts)
        callbacks = {i[3] for i in self.inputs if i[3]}
        # timer callbacks are paced roots: they never make a path unpaced
        others = [f for f, (kind, _) in roots.items()
                  if kind not in PACED_ROOTS and f not in callbacks]
        self.other_parents = {}
        self.from_others = _reach(others, self.unpaced, self.other_parents)
        self.reached = {}  # callback -> (functions reached, parents)

    def _reach_from(self, callback):
        if callback not in self.reached:
            parents = {}
            self.reached[callback] = (
                _reach([callback], self.unpaced, parents), parents)
        return self.reached[callback]

    def all_inputs(self, location, why):
        """The trigger that stands for every input of the node."""
        return Trigger(
            kind=TRIGGER_ALL, name=None, location=location, detail=why)

    def of(self, sites):
        """The triggers of a dependent publisher with these sites."""
        unpaced_sites = [s for s in sites if not self.is_paced(s.loops)]
        for site in unpaced_sites:
            if site.function in self.from_others:
                path = _bad_path(
                    site, self.facts, self.roots, self.other_parents)
                return [self.all_inputs(path.location, path.detail)]
        for kind, name, location, callback, _, _ in self.inputs:
            if callback is None or callback not in self.facts.functions:
                return [self.all_inputs(
                    location, f'the callback of the {kind} {name} at '
                    f'{location} could not be followed')]
        triggers = []
        for kind, name, location, callback, sync, listener in self.inputs:
            reached, parents = self._reach_from(callback)
            hit = [s for s in unpaced_sites if s.function in reached]
            if not hit:
                continue
            site = hit[0]
            path = [site.location]
            current = site.function
            while current != callback and current in parents:
                path.append(parents[current].location)
                current = parents[current].caller
            every = {s.every for s in hit}
            name_of = self.facts.functions[callback].name
            triggers.append(Trigger(
                kind=kind, name=name, location=location,
                detail=f'{name_of} publishes at {" <- ".join(path)}',
                sync=sync,
                every=every.pop() if len(every) == 1 else None))
        return triggers


def _inputs(facts):
    """(kind, name, location, callback, sync, listener) of each input.

    A listener (a tf TransformListener) has no callback of the user's:
    it only fills a buffer, so it drives nothing and is left out.
    """
    sync_of = {}
    for sync in facts.syncs:
        for handle in sync.inputs:
            sync_of.setdefault(handle, sync.location)
    inputs = []
    for subscriber in facts.subscribers:
        if subscriber.callback is None and _is_listener(subscriber):
            continue
        inputs.append((
            'subscriber', subscriber.topic, subscriber.location,
            subscriber.callback, sync_of.get(subscriber.handle), False))
    for service in facts.services:
        inputs.append(('service', service.name, service.location,
                       service.callback, None, False))
    for action in facts.actions:
        if action.role != 'server':
            continue
        for callback in action.callbacks:
            inputs.append(('action', action.name, action.location,
                           callback, None, False))
    # a plugin's host calls these when a request reaches it
    for function, kind in sorted(facts.host_roots.items()):
        if kind == ROOT_HOST_REQUEST and function in facts.functions:
            method = facts.functions[function]
            inputs.append(('host_request', method.name.split('::')[-1],
                           method.location, function, None, False))
    return inputs


def _is_listener(subscriber):
    """A class that subscribes by being created (tf listeners)."""
    api = ros_api.DECLARED.get(subscriber.api) or \
        python_api.CALLS.get(subscriber.api)
    return bool(api is not None and api.implicit_topics)
