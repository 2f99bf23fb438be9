# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Node assembly: a node's facts -> its labelled :class:`Node`.

The C++ (:mod:`colcon_rsia.package.analysis`) and the Python
(:mod:`colcon_rsia.package.python_analysis`) package analyses find a
node's functions (its ``seeds``) and merge the facts of the units it may
run; :func:`build_node` selects what the node runs, labels its publishers
(:mod:`colcon_rsia.package.labeling`) and builds the summary's node.
"""

import os

from colcon_rsia.package.labeling import label_publishers
from colcon_rsia.package.node_facts import handles_of
from colcon_rsia.package.node_facts import node_facts
from colcon_rsia.package.node_facts import resolve_namespace
from colcon_rsia.package.node_facts import select_functions
from colcon_rsia.package.node_facts import topic_param
from colcon_rsia.summary.kinds import ROOT_HOST_PERIODIC
from colcon_rsia.summary.nodes import LoadedNodelet
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.nodes import NodeAction
from colcon_rsia.summary.nodes import NodeClient
from colcon_rsia.summary.nodes import NodeService
from colcon_rsia.summary.nodes import NodeSubscriber
from colcon_rsia.summary.nodes import NodeTimer


def executable_nodes(package, executable, sources, path, merged, seeds,
                     library_files=frozenset()):
    """The node(s) an executable runs.

    One, unless its code names nodes in two or more classes (a ROS 2
    ``main`` spinning several ``rclcpp::Node`` subclasses in one
    executor): then each class is a node of its own, with its methods and
    what they call, and the id ``package/executable/node_name``.

    :param library_files: the sources of the package's library it links,
      relative to `path` (see node_facts.node_facts)
    """
    classes = _node_classes(merged, select_functions(merged, seeds))
    if len(classes) < 2:
        return [build_node(package, executable, 'executable', sources, path,
                           merged, seeds, library_files=library_files)]
    nodes = []
    for class_id, class_name in sorted(
            classes.items(), key=lambda item: item[1]):
        class_seeds = {f.id for f in merged.functions
                       if f.class_id == class_id}
        node = build_node(package, executable, 'executable', sources, path,
                          merged, class_seeds, library_files=library_files)
        short = node.name or class_name.split('::')[-1]
        node.id = f'{package}/{executable}/{short}'
        if any(n.id == node.id for n in nodes):
            node.id = f'{package}/{executable}/{class_name}'
        nodes.append(node)
    return nodes


def _node_classes(merged, function_ids):
    """{class id: class name} of the classes whose methods name a node."""
    functions = {f.id: f for f in merged.functions if f.id in function_ids}
    classes = {}
    for fact in merged.node_names:
        function = functions.get(fact.function)
        if function is not None and function.class_id:
            classes.setdefault(
                function.class_id, function.name.rsplit('::', 1)[0])
    return classes


def _node_name(facts):
    """(name, namespace) the node's code gives, when it gives one.

    The name is a literal, or a parameter (``Base(name) : Node(name)``)
    that the node's calls pass one literal to.
    """
    given = set()
    for fact in facts.node_names:
        name = fact.name
        if name is None and fact.name_param:
            # through every parameter the name was handed on from
            passed = set()
            for param in handles_of(facts, fact.name_param):
                passed |= facts.string_arguments.get(param, set())
            name = next(iter(passed)) if len(passed) == 1 else None
        if name:
            given.add((name, fact.namespace))
    if len(given) == 1:
        return given.pop()
    return None, None


def build_node(package, executable, kind, sources, path, merged, seeds,
               node_id=None, host=None, host_roots=None,
               private_handles=(), library_files=frozenset(),
               hierarchy=None):
    """The labelled node that runs the functions `seeds` and what they call.

    :param sources: the files (absolute) the node is built from
    :param merged: the merged facts of every unit the node may run
    :param node_id: default ``package/executable``
    :param host: a plugin's :class:`colcon_rsia.package.plugin_hosts.Host`
    :param host_roots: {function id: root kind} of the methods it calls
    :param private_handles: NodeHandle parameters the host gives in the
      plugin's own namespace
    :param library_files: see :func:`executable_nodes`
    :param hierarchy: a node that is an object of one class (a plugin):
      that class and its bases (see node_facts.select_functions)
    """
    facts = node_facts(merged, select_functions(merged, seeds, hierarchy),
                       library_files)
    facts.host = host
    facts.host_roots = dict(host_roots or {})
    for event in facts.host_events:
        # gzserver's world update: a callback the host calls every step
        if host is not None and event.api in host.periodic_events and \
                event.callback in facts.functions:
            facts.host_roots.setdefault(
                event.callback, ROOT_HOST_PERIODIC)
    for handle in private_handles:
        facts.namespaces[handle] = '~'
    publishers, roots = label_publishers(facts)
    names = {fid: f.name for fid, f in facts.functions.items()}
    node_name, namespace = _node_name(facts)
    return Node(
        id=node_id or f'{package}/{executable}', package=package,
        executable=executable, kind=kind,
        name=node_name, namespace=namespace,
        sources=sorted(os.path.relpath(s, path) for s in sources),
        files=sorted(set(merged.files) | {
            os.path.relpath(s, path) for s in sources}),
        publishers=sorted(publishers, key=lambda p: (p.location, p.topic or '')),
        subscribers=sorted((
            NodeSubscriber(
                topic=s.topic, topic_is_literal=s.topic_is_literal,
                msg_type=s.msg_type, api=s.api,
                callback=names.get(s.callback, s.callback),
                namespace=resolve_namespace(facts, s.nh),
                location=s.location, topic_param=topic_param(facts, s),
                origin=s.origin, made_in=s.made_in)
            for s in facts.subscribers),
            key=lambda s: (s.location, s.topic or '')),
        timers=[NodeTimer(
            api=t.api, callback=names.get(t.callback, t.callback),
            period=t.period, rate_hz=t.rate_hz, location=t.location)
            for t in facts.timers],
        services=[NodeService(
            name=s.name, api=s.api,
            callback=names.get(s.callback, s.callback), location=s.location)
            for s in facts.services],
        actions=_actions(facts, names),
        clients=[NodeClient(name=c.name, api=c.api, location=c.location)
                 for c in facts.clients],
        roots=roots, host=host.host if host is not None else None,
        loads=[LoadedNodelet(
            name=n.name, type=n.type, location=n.location)
            for n in facts.nodelet_loads if n.name and n.type])


def _actions(facts, names):
    """Actions, with callbacks registered later folded into their server."""
    actions = [a for a in facts.actions
               if not a.location.startswith('registration:')]
    by_handle = {a.handle: a for a in actions if a.handle}
    extra = {}
    for registration in facts.actions:
        if registration.location.startswith('registration:') and \
                registration.handle in by_handle:
            extra.setdefault(registration.handle, []).extend(
                registration.callbacks)
    return [NodeAction(
        name=a.name, api=a.api, role=a.role,
        callbacks=sorted({names.get(c, c) for c in
                          a.callbacks + extra.get(a.handle, [])}),
        location=a.location) for a in actions]
