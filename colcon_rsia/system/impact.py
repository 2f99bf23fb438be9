# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Impact analysis: the paper's Algorithm 2 and the traditional one."""

import difflib

from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.system.graph import ALL_INPUTS

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


# the models of rate dependency a dependent publisher edge is crossed by
PAPER = 'paper'      # every input of its node drives it (Algorithm 2)
TRIGGER = 'trigger'  # only the inputs whose callbacks reach it (triggers)
TRADITIONAL = 'traditional'  # data flow: every edge
MODELS = (PAPER, TRIGGER)


def crosses(data, via, model_name):
    """Whether a rate change arriving on topic `via` crosses an edge.

    :param data: the node -> topic edge's data
    :param via: the topic the change came in on; None: the node changed
      (its edges are all relabelled dependent)
    """
    if via is None or model_name == TRADITIONAL:
        return True
    if data['label'] == INDEPENDENT:
        return False
    if model_name == PAPER:
        return True
    triggers = data.get('triggers', {ALL_INPUTS})
    return ALL_INPUTS in triggers or via in triggers


def _impact(system, changed, model_name, untriggered=None):
    """Walk from the changed nodes; a state is (node, topic it came on)."""
    graph = system.graph
    impact = set()
    visited = set()
    todo = [(('node', c), None) for c in sorted(changed, reverse=True)]
    while todo:
        state = todo.pop()
        if state in visited:
            continue
        visited.add(state)
        current, via = state
        for topic in sorted(graph.successors(current)):
            data = graph.edges[current, topic]
            if not crosses(data, via, model_name):
                if untriggered is not None and \
                        data['label'] != INDEPENDENT:
                    untriggered.add((current[1], via, topic[1]))
                continue
            for subscriber in graph.successors(topic):
                # reached again through a cycle: listed, not re-walked
                impact.add(subscriber[1])
                todo.append((subscriber, topic[1]))
    return sorted(impact)


def rate_impact(system, changed, model_name=PAPER):
    """The nodes whose publishing rate may follow a change (Algorithm 2).

    :param model_name: ``paper`` (a dependent publisher follows every
      input of its node) or ``trigger`` (only the inputs that trigger it)
    """
    return _impact(system, changed, model_name)


def traditional_impact(system, changed):
    """Every node reachable along data flow from the changed nodes."""
    return _impact(system, changed, TRADITIONAL)


def not_triggered(system, changed):
    """Why the trigger model's set is smaller than the paper's.

    :returns: [{node, via, topic, triggers}]: the dependent edges the
      trigger walk reached on a topic that does not trigger them
    """
    untriggered = set()
    _impact(system, changed, TRIGGER, untriggered)
    return [_untriggered_json(system, *edge)
            for edge in sorted(untriggered)]


def _untriggered_json(system, node_id, via, topic):
    triggers = []
    for entry in system.instances[node_id].publishers:
        if entry['resolved'] == topic:
            triggers += [
                {'trigger': name,
                 'evidence': f'{trigger.detail} ({trigger.location})'
                 if trigger else 'no triggers recorded'}
                for name, trigger in entry.get('triggers', [])]
    return {'node': node_id, 'via': via, 'topic': topic,
            'triggers': triggers}


def impact_to_json(system, changed, model_name=PAPER):
    """The impact@1 contract (see docs/json.md); `changed` are instance ids.

    ``rate_impact`` is the set under `model_name`; both models' sets and
    the edges that make the trigger model's smaller are there too.
    """
    paper = rate_impact(system, changed, PAPER)
    trigger = rate_impact(system, changed, TRIGGER)
    return {
        'schema': IMPACT_SCHEMA,
        'changed': sorted(changed),
        'model': model_name,
        'rate_impact': paper if model_name == PAPER else trigger,
        'traditional_impact': traditional_impact(system, changed),
        'paper_impact': paper,
        'trigger_impact': trigger,
        'not_triggered': not_triggered(system, changed),
    }


def _state_edges(system, model_name):
    """Edges between walk states (node, topic it was reached on)."""
    graph = system.graph
    edges = []
    for topic in graph:
        if topic[0] != 'topic':
            continue
        for node in graph.successors(topic):
            for out in graph.successors(node):
                if crosses(graph.edges[node, out], topic[1], model_name):
                    edges += [((node[1], topic[1]), (subscriber[1], out[1]))
                              for subscriber in graph.successors(out)]
    return edges


def _closures(states, edges, bit):
    """Reflexive-transitive reachability of every state, as node bit sets.

    Computed once over the condensation (strongly connected components in
    reverse topological order), so that every node's impact set is a union
    of its successors' closures instead of a traversal of its own.
    """
    # imported here: loading the module (every colcon call does) must not
    # cost networkx's import time
    import networkx as nx
    graph = nx.DiGraph()
    graph.add_nodes_from(states)
    graph.add_edges_from(edges)
    condensed = nx.condensation(graph)
    closure_of_component = {}
    for component in reversed(list(nx.topological_sort(condensed))):
        bits = 0
        for member in condensed.nodes[component]['members']:
            bits |= bit[member[0]]
        for successor in condensed.successors(component):
            bits |= closure_of_component[successor]
        closure_of_component[component] = bits
    mapping = condensed.graph['mapping']
    return {state: closure_of_component[mapping[state]] for state in states}


def _ratio(part, whole):
    return round(part / whole, 3) if whole else 1.0


def impact_all(system, model_name=PAPER):
    """The impact set sizes of every node whose change reaches another.

    Leaf nodes (traditional impact empty) are left out, as in the paper's
    Fig. 3 and 7. A changed node reaches each subscriber of its topics
    (its own edges count as dependent) and from there whatever those
    reach: along the edges each model crosses (:func:`crosses`).
    ``rate_impact`` and ``ratio`` are those of `model_name`.
    """
    graph = system.graph
    nodes = sorted(system.instances)
    bit = {node: 1 << index for index, node in enumerate(nodes)}
    states = [(node[1], topic[1]) for topic in graph if topic[0] == 'topic'
              for node in graph.successors(topic)]
    closures = {
        name: _closures(states, _state_edges(system, name), bit)
        for name in (TRADITIONAL, PAPER, TRIGGER)}
    rows = []
    for node_id in nodes:
        sizes = {}
        for name, closure in closures.items():
            bits = 0
            for topic in graph.successors(('node', node_id)):
                for subscriber in graph.successors(topic):
                    bits |= closure[(subscriber[1], topic[1])]
            sizes[name] = bin(bits).count('1')
        if not sizes[TRADITIONAL]:
            continue
        rows.append({
            'id': node_id,
            'rate_impact': sizes[model_name],
            'traditional_impact': sizes[TRADITIONAL],
            'paper_impact': sizes[PAPER],
            'trigger_impact': sizes[TRIGGER],
        })
        if sizes[TRIGGER] < sizes[PAPER]:
            # the evidence of each difference
            rows[-1]['not_triggered'] = not_triggered(system, [node_id])
    count = len(rows)
    sums = {key: sum(r[key] for r in rows) for key in (
        'rate_impact', 'traditional_impact', 'paper_impact',
        'trigger_impact')}
    result = {
        'schema': IMPACT_ALL_SCHEMA,
        'model': model_name,
        'nodes': rows,
        'ratio': _ratio(sums['rate_impact'], sums['traditional_impact']),
        'paper_ratio': _ratio(sums['paper_impact'],
                              sums['traditional_impact']),
        'trigger_ratio': _ratio(sums['trigger_impact'],
                                sums['traditional_impact']),
        'trigger_to_paper': _ratio(sums['trigger_impact'],
                                   sums['paper_impact']),
    }
    for key, total in sums.items():
        result['average_' + key] = round(total / count, 3) if count else 0.0
    return result
