# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Workspace-wide reports: one directory with everything a reviewer needs.

:func:`colcon_rsia.report.writer.write_report` writes

* ``index.html``: self-contained (inline CSS, JS and SVG; nothing is
  fetched): the system graph (laid out by Graphviz ``dot`` when it is on
  PATH, see :mod:`colcon_rsia.report.drawing`) with pan, zoom, search and
  an evidence panel, the per-node impact table, per-node and per-topic
  tables, and a filter box;
* ``graph.svg``: the page's drawing of the graph on its own;
* ``graph.dot``: the graph for Graphviz;
* ``graph.json`` (graph@1) and, when nodes changed, ``impact.json``
  (impact@1);
* ``summary.md``: a short Markdown summary for a pull-request comment.

This module computes what they show (:func:`build_report`); ``html``,
``markdown`` and ``drawing`` render it and ``writer`` writes the files.
"""

from collections import deque
from dataclasses import dataclass
from dataclasses import field
from typing import Dict
from typing import List
from typing import Optional

from colcon_rsia import __version__
from colcon_rsia.render.graph import graph_to_json
from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.system.impact import impact_all
from colcon_rsia.system.impact import impact_to_json
from colcon_rsia.system.impact import PAPER

# the status of a node instance in a report
CHANGED = 'changed'
RATE = 'rate'                # in the rate-aware impact set
TRADITIONAL = 'traditional'  # only in the traditional impact set
UNAFFECTED = ''


@dataclass
class StoppedEdge:
    """An independent edge of a reached node: rate changes stop there."""

    node: str
    topic: str
    patterns: List[str]
    subscribers: List[str]
    held: List[str]           # its subscribers the rate change never reached

    def describe(self):
        """``/plan of pkg/planner (timer 5 Hz)``."""
        return f"{self.topic} of {self.node} ({', '.join(self.patterns)})"


@dataclass
class ReportData:
    """Everything the report files show, computed once."""

    system: object
    graph: dict
    all_impact: dict
    changed: Optional[List[str]] = None
    reasons: Dict[str, List[str]] = field(default_factory=dict)
    impact: Optional[dict] = None
    since: Optional[str] = None
    status: Dict[str, str] = field(default_factory=dict)
    via: Dict[str, str] = field(default_factory=dict)
    stopped: List[StoppedEdge] = field(default_factory=list)
    crossed: set = field(default_factory=set)
    version: str = __version__

    @property
    def notes(self):  # noqa: D102
        return list(self.system.notes)


def edge_patterns(data):
    """The distinct ``pattern rate`` of the publishers of an edge."""
    patterns = []
    for publisher in data.get('publishers', []):
        text = publisher.pattern
        if publisher.rate_hz:
            text += f' {publisher.rate_hz:g} Hz'
        if text not in patterns:
            patterns.append(text)
    return patterns or [data.get('label', DEPENDENT)]


def _propagation(system, changed):
    """Walk as Algorithm 2 does, recording how each node was reached.

    :returns: (via {id: how}, crossed edges, stopped {(node, topic): data})
    """
    graph = system.graph
    changed_vertices = {('node', c) for c in changed}
    via = {}
    crossed = set()
    stopped = {}
    visited = set()
    queue = deque(sorted(changed_vertices))
    while queue:
        current = queue.popleft()
        if current in visited:
            continue
        visited.add(current)
        for topic in sorted(graph.successors(current)):
            data = graph.edges[current, topic]
            relabelled = current in changed_vertices
            if data['label'] == INDEPENDENT and not relabelled:
                stopped[(current[1], topic[1])] = data
                continue
            crossed.add((current, topic))
            for subscriber in sorted(graph.successors(topic)):
                crossed.add((topic, subscriber))
                if subscriber[1] not in via:
                    how = data['label']
                    if relabelled and how == INDEPENDENT:
                        how = 'changed node: relabelled dependent'
                    via[subscriber[1]] = f'{topic[1]} of {current[1]} ({how})'
                if subscriber not in visited:
                    queue.append(subscriber)
    return via, crossed, stopped


def _held_by(system, stopped, reached):
    """The first stopped edge upstream of each node it holds back.

    For the nodes the traditional walk reaches and the rate-aware one does
    not.
    """
    graph = system.graph
    held = {}
    for edge in stopped:
        queue = deque(sorted(graph.successors(('topic', edge.topic))))
        seen = set()
        while queue:
            vertex = queue.popleft()
            if vertex in seen:
                continue
            seen.add(vertex)
            if vertex[0] == 'node' and vertex[1] not in reached:
                held.setdefault(vertex[1], edge)
            queue.extend(sorted(graph.successors(vertex)))
    return held


def build_report(system, *, changed=None, reasons=None, since=None,
                 model_name=PAPER):
    """Compute what the report shows.

    :param changed: instance ids of the changed nodes; None: no impact
      section
    :param reasons: {instance id: [why it counts as changed]}
    :param since: the ``--since`` revision, when the changes came from git
    """
    data = ReportData(
        system=system, graph=graph_to_json(system),
        all_impact=impact_all(system, model_name), since=since,
        status={i: UNAFFECTED for i in system.instances})
    if changed is None:
        return data
    data.changed = sorted(changed)
    data.reasons = {c: list((reasons or {}).get(c) or ['named with --changed'])
                    for c in data.changed}
    data.impact = impact_to_json(system, data.changed, model_name)
    for node_id in data.impact['traditional_impact']:
        data.status[node_id] = TRADITIONAL
    for node_id in data.impact['rate_impact']:
        data.status[node_id] = RATE
    for node_id in data.changed:
        data.status[node_id] = CHANGED
    via, data.crossed, stopped = _propagation(system, data.changed)
    rate = set(data.impact['rate_impact'])
    for (node_id, topic), edge in sorted(stopped.items()):
        subscribers = sorted(
            v[1] for v in system.graph.successors(('topic', topic)))
        if not subscribers:
            continue  # nothing to stop
        data.stopped.append(StoppedEdge(
            node=node_id, topic=topic, patterns=edge_patterns(edge),
            subscribers=subscribers,
            held=[s for s in subscribers if s not in rate]))
    for node_id in data.impact['rate_impact']:
        data.via[node_id] = 'via ' + via[node_id]
    held = _held_by(system, data.stopped, rate | set(data.changed))
    for node_id in data.impact['traditional_impact']:
        if node_id not in rate and node_id in held:
            data.via[node_id] = \
                f'data flow only: held by independent {held[node_id].describe()}'
    if model_name != PAPER:
        for edge in data.impact['not_triggered']:
            for subscriber in system.graph.successors(('topic', edge['topic'])):
                node_id = subscriber[1]
                if data.status[node_id] == TRADITIONAL and \
                        node_id not in data.via:
                    data.via[node_id] = \
                        f"held: {edge['via']} does not trigger " \
                        f"{edge['topic']} of {edge['node']}"
    return data
