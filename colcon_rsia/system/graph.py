# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The system graph: node instances, topics and labelled edges.

Vertices are ``('node', id)`` and ``('topic', global name)``. A publisher is
an edge node -> topic carrying its label (an edge is independent only when
every publisher of the node on that topic is); a subscription is an edge
topic -> node. Without a launch file every analysed node is one instance in
the root namespace, named after its executable.
"""

from dataclasses import dataclass
from dataclasses import field
from typing import Any
from typing import Dict
from typing import List
from typing import Optional
from typing import Tuple

from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.kinds import TRIGGER_ALL
from colcon_rsia.summary.nodes import Node
from colcon_rsia.system.names import join
from colcon_rsia.system.names import node_fqn
from colcon_rsia.system.names import resolve


@dataclass
class Instance:
    """One running node: its analysed model and where it runs."""

    id: str                        # node id; with a launch file its full name
    node: Optional[Node]     # None: its package was not analysed
    package: str
    executable: str
    name: str                      # the node's base name
    namespace: str = '/'
    remaps: List[Tuple[str, str]] = field(default_factory=list)
    params: Dict[str, object] = field(default_factory=dict)  # node-relative
    location: str = ''
    publishers: List[dict] = field(default_factory=list)
    subscribers: List[dict] = field(default_factory=list)
    # what nothing here tells: '' (its code or a launch file names it),
    # NAMED_BY_LOADER (its name, so its private names) or HOST_UNKNOWN
    # (also the namespace its host gives it); `note` says why
    unplaced: str = ''
    note: str = ''

    @property
    def fqn(self):  # noqa: D102
        return node_fqn(self.namespace, self.name)

    @property
    def kind(self):  # noqa: D102
        return self.node.kind if self.node is not None else 'unknown'


def _new_digraph():
    # imported when a graph is built, not with the module: networkx takes
    # ~50 ms to import, and every colcon call (--help, completion) loads
    # the rsia subverbs and with them this module
    import networkx
    return networkx.DiGraph()


@dataclass
class SystemGraph:
    """Instances, topics and the networkx graph joining them."""

    instances: Dict[str, Instance] = field(default_factory=dict)
    graph: Any = field(default_factory=_new_digraph)  # a networkx.DiGraph
    notes: List[str] = field(default_factory=list)
    # {package: why its last analysis failed} of the summaries used that
    # are older than that analysis (stale: the package may have changed)
    stale: Dict[str, str] = field(default_factory=dict)

    def topics(self):
        """The global names of all topics, sorted."""
        return sorted(v[1] for v in self.graph if v[0] == 'topic')

    def instances_of(self, node_id):
        """Ids of the instances an instance id or a node id names.

        A node id is that of the summary (``pkg/exe``, ``pkg/Plugin``,
        ``pkg/exe/node_name``) or ``pkg/exe`` for every node the
        executable runs.
        """
        return sorted(
            i.id for i in self.instances.values()
            if node_id in _names_of(i))

    def known_names(self):
        """Every name :meth:`instances_of` answers to, sorted."""
        return sorted(
            {name for i in self.instances.values() for name in _names_of(i)})


def _names_of(instance):
    """Its id, ``package/executable`` and the id of the node it runs."""
    names = {instance.id, f'{instance.package}/{instance.executable}'}
    if instance.node is not None:
        names.add(instance.node.id)
    return names


NAMED_BY_LOADER = 'name'
HOST_UNKNOWN = 'host'


def instances_from_summaries(summaries):
    """Every analysed node once, as it names itself (else its executable).

    This is what runs when no launch file is given: the name and namespace
    are those the code gives (``ros::init``, ``rclcpp::Node("name", "ns")``).
    A nodelet or plugin is named by what loads it: without that, its
    private names are not known, nor, for a plugin of a host the analysis
    does not know, its relative ones (:func:`placement`). The nodelets a
    node's code loads (``nodelet::Loader::load``) are instances of their
    own (:func:`loaded_nodelets`).
    """
    nodes = [node for summary in summaries for node in summary.nodes]
    instances = []
    for node in nodes:
        unplaced, note = placement(node)
        instance = Instance(
            id=node.id, node=node, package=node.package,
            executable=node.executable, name=node.name or node.executable,
            namespace=join('/', node.namespace or ''), unplaced=unplaced,
            note=note)
        instances.append(instance)
        instances += loaded_nodelets(instance, nodes)
    return instances


def placement(node):
    """(what is not known of where the node runs, why) without a launcher.

    A nodelet's name is the one its manager loads it under; a plugin's is
    its host's choice (a controller's key in the controller manager's
    parameters, the SDF's name of a Gazebo plugin), in the host's
    namespace: the root, as for every node no launch file places. A
    plugin of a base no host of the table has (a filter of a filter chain,
    an rviz display) runs in a process the analysis does not know.
    """
    if node.kind == 'nodelet':
        return NAMED_BY_LOADER, (
            'a nodelet is named by what loads it (a launch file, '
            'nodelet::Loader::load): its private names are not resolved')
    if node.kind != 'plugin' or node.name:
        return '', ''
    if node.host:
        return NAMED_BY_LOADER, (
            f'{node.host} loads and names this plugin (--launch with the '
            'host places it): its private names are not resolved')
    return HOST_UNKNOWN, (
        f'a plugin of {node.base_class or "an unknown base"}, whose host '
        'the analysis does not know: only its global names are resolved')


def loaded_nodelets(loader, nodes):
    """The instances of the nodelets a node's code loads by name.

    ``nodelet::Loader::load(name, type, ...)`` names the nodelet as a
    NodeHandle does: a relative name in the loading node's namespace.
    """
    if loader.node is None:
        return []
    by_id = {n.id: n for n in nodes if n.kind == 'nodelet'}
    found = []
    for load in loader.node.loads:
        node = by_id.get(load.type)
        fqn = resolve(load.name, node_name=loader.name,
                      namespace=loader.namespace)
        namespace, _, name = fqn.rpartition('/')
        instance = Instance(
            id=fqn, node=node, package=load.type.split('/')[0],
            executable=load.type, name=name, namespace=namespace or '/',
            remaps=list(loader.remaps),
            location=f'{loader.package}/{load.location}',
            note='' if node is not None else
            f'loaded by {loader.id} ({load.location}): not analysed')
        found.append(instance)
    return found


def build_graph(summaries, instances=None, notes=()):
    """Build the system graph.

    :param summaries: the package summaries
    :param instances: the node instances that run (from a launch file);
      None: every analysed node once (:func:`instances_from_summaries`)
    """
    if instances is None:
        instances = instances_from_summaries(summaries)
    system = SystemGraph(notes=list(notes))
    for instance in instances:
        system.instances[instance.id] = instance
    for instance in system.instances.values():
        _connect(system, instance)
    return system


def _topic_name(instance, entity):
    """The topic as the node uses it: literal, or from a parameter.

    A parameter's value (else its default) with what the code joins
    around it.
    """
    if entity.topic_is_literal:
        return entity.topic
    param = entity.topic_param
    if param is None:
        return None
    value = None
    if param.namespace.startswith('~'):
        # a private parameter: the launch file sets it inside the node
        key = join(param.namespace[1:], param.name).lstrip('/')
        value = instance.params.get(key)
    value = value if isinstance(value, str) else param.default
    return None if value is None else param.prefix + value + param.suffix


def _resolve(instance, entity):
    name = _topic_name(instance, entity)
    if _unplaced_name(instance, name, entity.namespace or ''):
        return None
    return resolve(
        name, node_name=instance.name, namespace=instance.namespace,
        handle_namespace=entity.namespace or '', remaps=instance.remaps)


def _unplaced_name(instance, name, handle_namespace):
    """Whether a name depends on what nothing tells of the instance."""
    if not instance.unplaced or not name or name.startswith('/'):
        return False
    if name.startswith('~') or handle_namespace.startswith('~'):
        return True  # private: in the node's name
    return instance.unplaced == HOST_UNKNOWN and \
        not handle_namespace.startswith('/')


def _connect(system, instance):
    graph = system.graph
    vertex = ('node', instance.id)
    graph.add_node(vertex)
    if instance.node is None:
        if instance.note:
            system.notes.append(f'{instance.id}: {instance.note}')
        _connect_unknown(system, instance)
        return
    for publisher in instance.node.publishers:
        resolved = _resolve(instance, publisher)
        instance.publishers.append(
            {'publisher': publisher, 'resolved': resolved})
        if resolved is not None:
            _add_publisher_edge(graph, vertex, ('topic', resolved), publisher)
    for subscriber in instance.node.subscribers:
        resolved = _resolve(instance, subscriber)
        instance.subscribers.append(
            {'subscriber': subscriber, 'resolved': resolved})
        if resolved is None:
            continue
        topic = ('topic', resolved)
        if graph.has_edge(topic, vertex):
            graph.edges[topic, vertex]['subscribers'].append(subscriber)
        else:
            graph.add_edge(topic, vertex, subscribers=[subscriber])
    _attach_triggers(system, instance)
    if instance.note and any(
            _unplaced_name(instance, _topic_name(instance, e),
                           e.namespace or '')
            for e in instance.node.publishers + instance.node.subscribers):
        system.notes.append(f'{instance.id}: {instance.note}')


ALL_INPUTS = '*'


def resolve_triggers(instance, publisher):
    """The triggers of a dependent publisher as the instance runs it.

    :returns: [(name, trigger or None)]: resolved topic names,
      ``service:<name>``, ``action:<name>``, or ``*`` (every input; the
      trigger is None for a summary written before triggers were recorded)
    """
    if publisher.label == INDEPENDENT:
        return []
    if publisher.triggers is None:
        return [(ALL_INPUTS, None)]
    resolved = []
    for trigger in publisher.triggers:
        if trigger.kind == TRIGGER_ALL:
            resolved.append((ALL_INPUTS, trigger))
        elif trigger.kind == 'subscriber':
            names = {s['resolved'] for s in instance.subscribers
                     if s['subscriber'].location == trigger.location and
                     s['subscriber'].topic == trigger.name}
            if None in names or not names:
                # a topic we cannot name: the edge follows every input
                resolved.append((ALL_INPUTS, trigger))
            resolved += [(name, trigger) for name in sorted(names - {None})]
        else:
            resolved.append((f'{trigger.kind}:{trigger.name}', trigger))
    return resolved


def _attach_triggers(system, instance):
    """Each dependent publisher edge: the topics that trigger it."""
    vertex = ('node', instance.id)
    for entry in instance.publishers:
        publisher = entry['publisher']
        entry['triggers'] = resolve_triggers(instance, publisher)
        if entry['resolved'] is None or publisher.label == INDEPENDENT:
            continue
        data = system.graph.edges[vertex, ('topic', entry['resolved'])]
        data.setdefault('triggers', set()).update(
            name for name, _ in entry['triggers'])


def _add_publisher_edge(graph, vertex, topic, publisher):
    if graph.has_edge(vertex, topic):
        data = graph.edges[vertex, topic]
        data['publishers'].append(publisher)
        if publisher.label != INDEPENDENT:
            data['label'] = DEPENDENT
    else:
        graph.add_edge(vertex, topic, label=publisher.label,
                       publishers=[publisher])


def _connect_unknown(system, instance):
    """A node whose code was not analysed: assume the worst.

    Its remap targets are the only topics we know it uses; it may read and
    write each of them, and what it writes follows what it reads.
    """
    graph = system.graph
    vertex = ('node', instance.id)
    for _, target in instance.remaps:
        resolved = resolve(target, node_name=instance.name,
                           namespace=instance.namespace)
        topic = ('topic', resolved)
        graph.add_edge(topic, vertex, subscribers=[])
        graph.add_edge(vertex, topic, label=DEPENDENT, publishers=[],
                       triggers={ALL_INPUTS})
