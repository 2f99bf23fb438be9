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
from typing import Dict
from typing import List

from colcon_rsia import model
from colcon_rsia.names import node_fqn
from colcon_rsia.names import resolve
import networkx as nx

GRAPH_SCHEMA = 'colcon-rsia/graph@1'


@dataclass
class Instance:
    """One running node: its analysed model and where it runs."""

    id: str
    node: model.Node
    name: str                      # the node's base name
    namespace: str = '/'
    publishers: List[dict] = field(default_factory=list)
    subscribers: List[dict] = field(default_factory=list)

    @property
    def fqn(self):  # noqa: D102
        return node_fqn(self.namespace, self.name)


@dataclass
class SystemGraph:
    """Instances, topics and the networkx graph joining them."""

    instances: Dict[str, Instance] = field(default_factory=dict)
    graph: nx.DiGraph = field(default_factory=nx.DiGraph)

    def topics(self):
        """The global names of all topics, sorted."""
        return sorted(v[1] for v in self.graph if v[0] == 'topic')


def build_graph(summaries):
    """Build the system graph of analysed packages (one instance a node)."""
    system = SystemGraph()
    for summary in summaries:
        for node in summary.nodes:
            instance = Instance(id=node.id, node=node, name=node.executable)
            system.instances[node.id] = instance
    for instance in system.instances.values():
        _connect(system, instance)
    return system


def _connect(system, instance):
    graph = system.graph
    vertex = ('node', instance.id)
    graph.add_node(vertex)
    for publisher in instance.node.publishers:
        resolved = resolve(
            publisher.topic if publisher.topic_is_literal else None,
            node_name=instance.name, namespace=instance.namespace,
            handle_namespace=publisher.namespace or '')
        instance.publishers.append(
            {'publisher': publisher, 'resolved': resolved})
        if resolved is None:
            continue
        topic = ('topic', resolved)
        if graph.has_edge(vertex, topic):
            data = graph.edges[vertex, topic]
            data['publishers'].append(publisher)
            if publisher.label != model.INDEPENDENT:
                data['label'] = model.DEPENDENT
        else:
            graph.add_edge(vertex, topic, label=publisher.label,
                           publishers=[publisher])
    for subscriber in instance.node.subscribers:
        resolved = resolve(
            subscriber.topic if subscriber.topic_is_literal else None,
            node_name=instance.name, namespace=instance.namespace,
            handle_namespace=subscriber.namespace or '')
        instance.subscribers.append(
            {'subscriber': subscriber, 'resolved': resolved})
        if resolved is None:
            continue
        topic = ('topic', resolved)
        if graph.has_edge(topic, vertex):
            graph.edges[topic, vertex]['subscribers'].append(subscriber)
        else:
            graph.add_edge(topic, vertex, subscribers=[subscriber])


def graph_to_json(system):
    """The graph@1 contract (see the README)."""
    nodes = []
    for instance in sorted(system.instances.values(), key=lambda i: i.id):
        node = instance.node
        nodes.append({
            'id': instance.id,
            'name': instance.fqn,
            'package': node.package,
            'executable': node.executable,
            'kind': node.kind,
            'publishers': [{
                'topic': p['publisher'].topic,
                'resolved': p['resolved'],
                'msg_type': p['publisher'].msg_type,
                'label': p['publisher'].label,
                'pattern': p['publisher'].pattern,
                'rate_hz': p['publisher'].rate_hz,
                'api': p['publisher'].api,
                'location': p['publisher'].location,
                'evidence': [
                    {'kind': e.kind, 'location': e.location,
                     'detail': e.detail}
                    for e in p['publisher'].evidence],
            } for p in instance.publishers],
            'subscribers': [{
                'topic': s['subscriber'].topic,
                'resolved': s['resolved'],
                'msg_type': s['subscriber'].msg_type,
                'callback': s['subscriber'].callback,
                'api': s['subscriber'].api,
                'location': s['subscriber'].location,
            } for s in instance.subscribers],
            'services': [{
                'name': s.name, 'api': s.api, 'callback': s.callback,
                'location': s.location} for s in node.services],
            'actions': [{
                'name': a.name, 'api': a.api, 'role': a.role,
                'callbacks': a.callbacks, 'location': a.location}
                for a in node.actions],
        })
    topics = []
    for name in system.topics():
        vertex = ('topic', name)
        topics.append({
            'name': name,
            'publishers': sorted(
                v[1] for v in system.graph.predecessors(vertex)),
            'subscribers': sorted(
                v[1] for v in system.graph.successors(vertex)),
        })
    return {'schema': GRAPH_SCHEMA, 'nodes': nodes, 'topics': topics}


def graph_to_dot(system, *, changed=(), rate_impact=(), traditional=()):
    """Graphviz DOT: nodes as ellipses, topics as boxes, independent dashed."""
    def quote(text):
        return '"' + text.replace('\\', '\\\\').replace('"', '\\"') + '"'
    lines = ['digraph rsia {', '  rankdir=LR;',
             '  node [fontname="Helvetica", fontsize=10];']
    for instance in sorted(system.instances.values(), key=lambda i: i.id):
        style = 'filled'
        color = 'white'
        if instance.id in changed:
            color = '#f4a261'
        elif instance.id in rate_impact:
            color = '#e76f51'
        elif instance.id in traditional:
            color = '#e9c46a'
        lines.append(
            f'  {quote("node:" + instance.id)} [label={quote(instance.id)}, '
            f'shape=ellipse, style={style}, fillcolor="{color}"];')
    for name in system.topics():
        lines.append(
            f'  {quote("topic:" + name)} [label={quote(name)}, shape=box];')
    for source, target, data in sorted(system.graph.edges(data=True)):
        attributes = ''
        if source[0] == 'node':
            if data['label'] == model.INDEPENDENT:
                attributes = ' [style=dashed, label="independent"]'
        lines.append(
            f'  {quote(source[0] + ":" + source[1])} -> '
            f'{quote(target[0] + ":" + target[1])}{attributes};')
    lines.append('}')
    return '\n'.join(lines) + '\n'


def graph_to_text(system):
    """A readable listing of nodes, their edges and labels."""
    lines = []
    for instance in sorted(system.instances.values(), key=lambda i: i.id):
        node = instance.node
        lines.append(f'{instance.id} ({node.kind}, {instance.fqn})')
        for p in instance.publishers:
            publisher = p['publisher']
            rate = f' {publisher.rate_hz:g} Hz' if publisher.rate_hz else ''
            lines.append(
                f'  publishes {p["resolved"] or "?" + str(publisher.topic)}'
                f' [{publisher.label}: {publisher.pattern}{rate}]'
                f' {publisher.location}')
        for s in instance.subscribers:
            subscriber = s['subscriber']
            lines.append(
                f'  subscribes {s["resolved"] or "?" + str(subscriber.topic)}'
                f' -> {subscriber.callback} {subscriber.location}')
    return '\n'.join(lines) + '\n'
