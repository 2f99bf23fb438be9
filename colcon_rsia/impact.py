# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Impact analysis: the paper's Algorithm 2 and the traditional one."""

import difflib

from colcon_rsia import model
import networkx as nx

IMPACT_SCHEMA = 'colcon-rsia/impact@1'
IMPACT_ALL_SCHEMA = 'colcon-rsia/impact-all@1'


class UnknownNodeError(ValueError):
    """A changed node that is not in the graph."""


def expand_changed(system, changed):
    """The instance ids meant by the changed names, sorted.

    A name is an instance id (a node id, or with a launch file the full
    name ``/robot/laser_front``) or ``package/executable`` for every
    instance of that executable.

    :raises UnknownNodeError: naming the closest known names
    """
    known = system.known_names()
    expanded = set()
    for name in changed:
        ids = system.instances_of(name)
        if not ids:
            close = difflib.get_close_matches(name, known, n=5, cutoff=0.4)
            if close:
                hint = f"; closest known: {', '.join(close)}"
            elif known:
                hint = f"; known nodes: {', '.join(known[:10])}"
            else:
                hint = '; no node has been analysed yet'
            raise UnknownNodeError(f"unknown node '{name}'{hint}")
        expanded.update(ids)
    return sorted(expanded)


def _impact(system, changed, rate_aware):
    graph = system.graph
    changed_vertices = {('node', c) for c in changed}
    impact = set()
    visited = set()
    for start in sorted(changed_vertices):
        todo = [start]
        while todo:
            current = todo.pop()
            if current in visited:
                continue
            visited.add(current)
            for topic in graph.successors(current):
                label = graph.edges[current, topic]['label']
                # a changed node's edges are all relabelled dependent
                if rate_aware and label == model.INDEPENDENT and \
                        current not in changed_vertices:
                    continue
                for subscriber in graph.successors(topic):
                    # reached again through a cycle: listed, not re-walked
                    impact.add(subscriber[1])
                    if subscriber not in visited:
                        todo.append(subscriber)
    return sorted(impact)


def rate_impact(system, changed):
    """The nodes whose publishing rate may follow a change (Algorithm 2)."""
    return _impact(system, changed, rate_aware=True)


def traditional_impact(system, changed):
    """Every node reachable along data flow from the changed nodes."""
    return _impact(system, changed, rate_aware=False)


def impact_to_json(system, changed):
    """The impact@1 contract (see the README); `changed` are instance ids."""
    return {
        'schema': IMPACT_SCHEMA,
        'changed': sorted(changed),
        'rate_impact': rate_impact(system, changed),
        'traditional_impact': traditional_impact(system, changed),
    }


def _node_edges(system):
    """Node-to-node edges: {node: {successor: reached by a dependent edge}}."""
    graph = system.graph
    edges = {}
    for vertex in graph:
        if vertex[0] != 'node':
            continue
        successors = edges.setdefault(vertex[1], {})
        for topic in graph.successors(vertex):
            dependent = graph.edges[vertex, topic]['label'] != \
                model.INDEPENDENT
            for subscriber in graph.successors(topic):
                successors[subscriber[1]] = \
                    successors.get(subscriber[1], False) or dependent
    return edges


def _closures(nodes, edges, keep):
    """Reflexive-transitive reachability of every node, as bit sets.

    Computed once over the condensation (strongly connected components in
    reverse topological order), so that every node's impact set is a union
    of its successors' closures instead of a traversal of its own.
    """
    graph = nx.DiGraph()
    graph.add_nodes_from(nodes)
    graph.add_edges_from(
        (u, v) for u, successors in edges.items()
        for v, flag in successors.items() if keep(flag))
    condensed = nx.condensation(graph)
    bit = {node: 1 << index for index, node in enumerate(nodes)}
    closure_of_component = {}
    for component in reversed(list(nx.topological_sort(condensed))):
        bits = 0
        for member in condensed.nodes[component]['members']:
            bits |= bit[member]
        for successor in condensed.successors(component):
            bits |= closure_of_component[successor]
        closure_of_component[component] = bits
    mapping = condensed.graph['mapping']
    return {node: closure_of_component[mapping[node]] for node in nodes}


def impact_all(system):
    """Both impact sizes for every node whose change reaches another node.

    Leaf nodes (traditional impact empty) are left out, as in the paper's
    Fig. 3 and 7. A changed node reaches each subscriber of its topics
    (its own edges count as dependent) and from there whatever those reach:
    along dependent edges for the rate-aware set, along every edge for the
    traditional one.
    """
    nodes = sorted(system.instances)
    edges = _node_edges(system)
    dependent_closure = _closures(nodes, edges, lambda dependent: dependent)
    any_closure = _closures(nodes, edges, lambda dependent: True)
    rows = []
    for node_id in nodes:
        successors = edges.get(node_id, {})
        traditional = rate = 0
        for successor in successors:
            traditional |= any_closure[successor]
            rate |= dependent_closure[successor]
        if not traditional:
            continue
        rows.append({
            'id': node_id,
            'rate_impact': bin(rate).count('1'),
            'traditional_impact': bin(traditional).count('1'),
        })
    rate_sum = sum(r['rate_impact'] for r in rows)
    traditional_sum = sum(r['traditional_impact'] for r in rows)
    count = len(rows)
    return {
        'schema': IMPACT_ALL_SCHEMA,
        'nodes': rows,
        'average_rate_impact': round(rate_sum / count, 3) if count else 0.0,
        'average_traditional_impact':
            round(traditional_sum / count, 3) if count else 0.0,
        'ratio': round(rate_sum / traditional_sum, 3)
        if traditional_sum else 1.0,
    }
