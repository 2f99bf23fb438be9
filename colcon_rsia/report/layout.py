# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A small deterministic layered layout of the system graph.

Vertices (node instances and topics) are put in rows, top to bottom, along
data flow: cycles are broken by reversing the back edges of a depth-first
search in name order, each vertex goes into the row of its longest path from
a source, an edge spanning several rows gets a narrow invisible waypoint in
each row it crosses (so that it runs between boxes, not through them), and
the vertices and waypoints of each row are ordered by a few barycenter
sweeps. Same graph, same picture.
"""

from dataclasses import dataclass
from dataclasses import field
from typing import Dict
from typing import List
from typing import Tuple

# measures in px; the label width is estimated from its length
CHAR_WIDTH = 7.0
BOX_PADDING = 18.0
BOX_HEIGHT = 26.0
BOX_GAP = 24.0         # between the boxes of a row
WAYPOINT_WIDTH = 8.0   # the room an edge takes crossing a row
ROW_GAP = 34.0         # between rows
MARGIN = 20.0
SWEEPS = 8


@dataclass
class Box:
    """Where a vertex (or an edge's waypoint) is drawn."""

    vertex: Tuple[str, str]
    layer: int
    x: float = 0.0
    y: float = 0.0
    width: float = 0.0
    height: float = BOX_HEIGHT


@dataclass
class Layout:
    """The boxes of the vertices, each edge's waypoints, and the size.

    ``waypoints[(source, target)]`` are the boxes an edge passes on its way
    from source to target (in that order; empty between adjacent rows).
    ``reversed_edges`` are the edges drawn upwards (they close a cycle).
    """

    boxes: Dict[Tuple[str, str], Box] = field(default_factory=dict)
    waypoints: Dict[tuple, List[Box]] = field(default_factory=dict)
    reversed_edges: List[Tuple[tuple, tuple]] = field(default_factory=list)
    width: float = 0.0
    height: float = 0.0


def _key(vertex):
    # nodes before topics of the same name; then by name
    return (vertex[1], vertex[0])


def label_width(text):
    """The estimated width of a label's box."""
    return BOX_PADDING + CHAR_WIDTH * len(text)


def _width(vertex):
    if vertex[0] == 'waypoint':
        return WAYPOINT_WIDTH
    return label_width(vertex[1])


def break_cycles(vertices, edges):
    """The edges a depth-first search in name order finds going back.

    :param vertices: all vertices
    :param edges: {vertex: sorted successors}
    :returns: the set of back edges (reversing them leaves a DAG)
    """
    indegree = {v: 0 for v in vertices}
    for source in vertices:
        for target in edges[source]:
            indegree[target] += 1
    # start at the sources, then wherever is left, in name order
    starts = sorted((v for v in vertices if indegree[v] == 0), key=_key) + \
        sorted((v for v in vertices if indegree[v] != 0), key=_key)
    state = {}  # 1: on the stack, 2: done
    back = set()
    for start in starts:
        if start in state:
            continue
        state[start] = 1
        stack = [(start, iter(edges[start]))]
        while stack:
            vertex, successors = stack[-1]
            for successor in successors:
                if state.get(successor) == 1:
                    back.add((vertex, successor))
                elif successor not in state:
                    state[successor] = 1
                    stack.append((successor, iter(edges[successor])))
                    break
            else:
                state[vertex] = 2
                stack.pop()
    return back


def layered_layout(graph):
    """Lay out a networkx DiGraph of ``('node'|'topic', name)`` vertices."""
    vertices = sorted(graph.nodes, key=_key)
    edges = {v: sorted(graph.successors(v), key=_key) for v in vertices}
    back = break_cycles(vertices, edges)
    dag = {v: [] for v in vertices}
    predecessors = {v: [] for v in vertices}
    for source in vertices:
        for target in edges[source]:
            if source == target:
                continue
            a, b = (target, source) if (source, target) in back else \
                (source, target)
            if b not in dag[a]:
                dag[a].append(b)
                predecessors[b].append(a)
    layer = _longest_path_layers(vertices, dag, predecessors)
    # a topic nobody publishes sits just above its first subscriber
    for vertex in vertices:
        if vertex[0] == 'topic' and not predecessors[vertex] and dag[vertex]:
            layer[vertex] = max(0, min(layer[s] for s in dag[vertex]) - 1)
    chains = _add_waypoints(vertices, dag, predecessors, layer)
    rows = {}
    for vertex in sorted(layer, key=_key):
        rows.setdefault(layer[vertex], []).append(vertex)
    order = [rows.get(i, []) for i in range(max(rows, default=-1) + 1)]
    order = _order_rows(order, predecessors, dag)
    layout = Layout(reversed_edges=sorted(back, key=lambda e: (
        _key(e[0]), _key(e[1]))))
    _place(layout, order, layer, predecessors, dag)
    for source in vertices:
        for target in edges[source]:
            if source == target:
                continue
            if (source, target) in back:
                points = list(reversed(chains.get((target, source), [])))
            else:
                points = chains.get((source, target), [])
            layout.waypoints[(source, target)] = [
                layout.boxes[p] for p in points]
    for vertex in list(layout.boxes):
        if vertex[0] == 'waypoint':
            del layout.boxes[vertex]
    return layout


def _add_waypoints(vertices, dag, predecessors, layer):
    """Split every DAG edge longer than one row by waypoint vertices.

    :returns: {(a, b): [waypoints from a down to b]}
    """
    chains = {}
    count = 0
    for a in vertices:
        for b in list(dag[a]):
            if layer[b] - layer[a] <= 1:
                continue
            chain = []
            previous = a
            for row in range(layer[a] + 1, layer[b]):
                count += 1
                # the name sorts a waypoint after the vertices of its row
                waypoint = ('waypoint', f'~{count:06d}')
                layer[waypoint] = row
                dag[waypoint] = []
                predecessors[waypoint] = []
                _relink(dag, predecessors, previous, waypoint)
                chain.append(waypoint)
                previous = waypoint
            _relink(dag, predecessors, previous, b)
            dag[a].remove(b)
            predecessors[b].remove(a)
            chains[(a, b)] = chain
    return chains


def _relink(dag, predecessors, a, b):
    dag[a].append(b)
    predecessors[b].append(a)


def _longest_path_layers(vertices, dag, predecessors):
    remaining = {v: len(predecessors[v]) for v in vertices}
    ready = [v for v in vertices if remaining[v] == 0]
    layer = {v: 0 for v in vertices}
    while ready:
        ready.sort(key=_key)
        vertex = ready.pop(0)
        for target in dag[vertex]:
            layer[target] = max(layer[target], layer[vertex] + 1)
            remaining[target] -= 1
            if remaining[target] == 0:
                ready.append(target)
    return layer


def _order_rows(order, predecessors, successors):
    """Barycenter sweeps, downwards then upwards; stable ties."""
    position = {}
    for row in order:
        for index, vertex in enumerate(row):
            position[vertex] = index
    for sweep in range(SWEEPS):
        downwards = sweep % 2 == 0
        indices = range(1, len(order)) if downwards else \
            range(len(order) - 2, -1, -1)
        reference = predecessors if downwards else successors
        for i in indices:
            row = order[i]

            def barycenter(vertex):
                linked = [position[v] for v in reference[vertex]]
                if not linked:
                    return position[vertex]
                return sum(linked) / len(linked)
            row.sort(key=lambda v: (barycenter(v), position[v], _key(v)))
            for index, vertex in enumerate(row):
                position[vertex] = index
    return order


def _place(layout, order, layer, predecessors, successors):
    """Rows top to bottom; each box pulled under the boxes it links to.

    Rows start centred; then, in sweeps down and up, every box wants the
    mean centre of its neighbours in the row before; the wishes are made
    to fit the row's order and gaps once pushing right and once pushing
    left, and the two are averaged (both fit, so the average does).
    """
    centre = {}
    widths = [
        sum(_width(v) for v in row) + max(0, len(row) - 1) * BOX_GAP
        for row in order]
    widest = max(widths, default=0.0)
    for row, width in zip(order, widths):
        x = (widest - width) / 2
        for vertex in row:
            centre[vertex] = x + _width(vertex) / 2
            x += _width(vertex) + BOX_GAP
    for sweep in range(SWEEPS):
        downwards = sweep % 2 == 0
        reference = predecessors if downwards else successors
        rows = order[1:] if downwards else list(reversed(order[:-1]))
        for row in rows:
            wish = []
            for vertex in row:
                linked = [centre[v] for v in reference[vertex]]
                wish.append(sum(linked) / len(linked) if linked
                            else centre[vertex])
            _fit(row, wish, centre)
    left = min((centre[v] - _width(v) / 2 for v in centre), default=0.0)
    right = max((centre[v] + _width(v) / 2 for v in centre), default=0.0)
    y = MARGIN
    for row in order:
        for vertex in row:
            layout.boxes[vertex] = Box(
                vertex=vertex, layer=layer[vertex],
                x=MARGIN + centre[vertex] - _width(vertex) / 2 - left, y=y,
                width=_width(vertex))
        y += BOX_HEIGHT + ROW_GAP
    layout.height = max(y - ROW_GAP + MARGIN, 2 * MARGIN)
    layout.width = right - left + 2 * MARGIN


def _fit(row, wish, centre):
    """Centres as close to the wishes as the order and the gaps allow."""
    count = len(row)
    if not count:
        return
    half = [_width(v) / 2 for v in row]
    pushed_right = list(wish)
    for i in range(1, count):
        pushed_right[i] = max(
            pushed_right[i],
            pushed_right[i - 1] + half[i - 1] + BOX_GAP + half[i])
    pushed_left = list(wish)
    for i in range(count - 2, -1, -1):
        pushed_left[i] = min(
            pushed_left[i],
            pushed_left[i + 1] - half[i + 1] - BOX_GAP - half[i])
    for i, vertex in enumerate(row):
        centre[vertex] = (pushed_right[i] + pushed_left[i]) / 2
