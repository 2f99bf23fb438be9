# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Where the page draws each vertex, edge and cluster of the system graph.

The layout is Graphviz's: ``dot -Tjson0`` lays out a graph made for it
(left to right along data flow, node instances clustered by namespace, or
by package when everything runs in one namespace; each box as wide as its
label) and the positions it computes are read back. The page draws its own
SVG from them, so that it can carry the impact classes and the evidence.

A hub topic (one with many endpoints spread over several clusters, such as
``/tf``) is drawn once per cluster it touches, so that its edges stay
inside their clusters instead of converging on one box.

Without ``dot`` (or when it fails) the small built-in layered layout of
:mod:`colcon_rsia.report.layout` is used: top to bottom, no clusters, plain
edge routing; the caller gets a note saying so.
"""

from dataclasses import dataclass
from dataclasses import field
import json
import shutil
import subprocess
from typing import List
from typing import Optional
from typing import Tuple

from colcon_rsia.report.layout import BOX_HEIGHT
from colcon_rsia.report.layout import label_width
from colcon_rsia.report.layout import layered_layout

DOT_TIMEOUT_S = 120
POINTS_PER_INCH = 72.0
# a topic with this many distinct endpoints, in two or more clusters, is
# drawn once per cluster
HUB_ENDPOINTS = 12
MARGIN = 12.0
BUILT_IN = "the page's graph is drawn by the simple built-in layout " \
    '(top to bottom, no clusters)'


@dataclass
class DrawnVertex:
    """A box: a node instance, a topic, or one copy of a hub topic."""

    key: str                        # unique in the drawing: v0, v1, ...
    vertex: Tuple[str, str]         # ('node', id) or ('topic', name)
    cluster: Optional[str] = None   # key of its cluster
    copies: int = 1                 # how many boxes its topic has
    x: float = 0.0                  # top left
    y: float = 0.0
    width: float = 0.0
    height: float = BOX_HEIGHT

    @property
    def label(self):  # noqa: D102
        return self.vertex[1]


@dataclass
class DrawnEdge:
    """An edge of the system graph between two boxes."""

    source: str                     # vertex keys
    target: str
    edge: Tuple[tuple, tuple]       # the system graph's edge it draws
    path: str = ''                  # SVG path data


@dataclass
class Cluster:
    """A box around the vertices of one namespace or package."""

    key: str
    label: str
    members: List[str] = field(default_factory=list)  # vertex keys
    x: float = 0.0
    y: float = 0.0
    width: float = 0.0
    height: float = 0.0


@dataclass
class Drawing:
    """The whole picture, in px, y downwards."""

    vertices: List[DrawnVertex] = field(default_factory=list)
    edges: List[DrawnEdge] = field(default_factory=list)
    clusters: List[Cluster] = field(default_factory=list)
    width: float = 0.0
    height: float = 0.0
    engine: str = 'dot'             # or 'built-in'


def _fmt(number):
    return f'{number:.1f}'.rstrip('0').rstrip('.')


def plan_drawing(system):
    """The boxes, edges and clusters to draw, without positions."""
    graph = system.graph
    instances = sorted(system.instances.values(), key=lambda i: i.id)
    by_namespace = len({i.namespace for i in instances}) > 1
    group_of = {}
    for instance in instances:
        if by_namespace:
            group_of[instance.id] = f'namespace {instance.namespace}'
        else:
            group_of[instance.id] = f'package {instance.package}'
    sizes = {}
    for group in group_of.values():
        sizes[group] = sizes.get(group, 0) + 1
    # a cluster of one node would only add a frame
    group_of = {i: g for i, g in group_of.items() if sizes[g] > 1}

    drawing = Drawing()
    clusters = {}

    def cluster_key(group):
        if group is None:
            return None
        if group not in clusters:
            clusters[group] = Cluster(key=f'c{len(clusters)}', label=group)
            drawing.clusters.append(clusters[group])
        return clusters[group].key

    def add(vertex, group, copies=1):
        drawn = DrawnVertex(
            key=f'v{len(drawing.vertices)}', vertex=vertex,
            cluster=cluster_key(group), copies=copies,
            width=label_width(vertex[1]))
        drawing.vertices.append(drawn)
        if drawn.cluster is not None:
            clusters[group].members.append(drawn.key)
        return drawn.key

    node_key = {}
    for instance in instances:
        node_key[instance.id] = add(
            ('node', instance.id), group_of.get(instance.id))
    # {(topic vertex, group): key}
    topic_key = {}
    for name in system.topics():
        vertex = ('topic', name)
        endpoints = {v[1] for v in graph.predecessors(vertex)} | \
            {v[1] for v in graph.successors(vertex)}
        groups = sorted({group_of.get(e) for e in endpoints},
                        key=lambda g: (g is not None, g or ''))
        if len(endpoints) >= HUB_ENDPOINTS and len(groups) > 1:
            for group in groups:
                topic_key[(vertex, group)] = add(vertex, group, len(groups))
        else:
            group = groups[0] if len(groups) == 1 else None
            key = add(vertex, group)
            for endpoint_group in groups or [None]:
                topic_key[(vertex, endpoint_group)] = key

    for source, target in sorted(graph.edges):
        if source[0] == 'node':
            keys = (node_key[source[1]],
                    topic_key[(target, group_of.get(source[1]))])
        else:
            keys = (topic_key[(source, group_of.get(target[1]))],
                    node_key[target[1]])
        drawing.edges.append(DrawnEdge(*keys, edge=(source, target)))
    return drawing


# --- Graphviz ---------------------------------------------------------------

def _quote(text):
    return '"' + text.replace('\\', '\\\\').replace('"', '\\"') + '"'


def layout_dot_source(drawing):
    """The DOT text Graphviz lays out (boxes of fixed size, no labels)."""
    lines = [
        'digraph layout {',
        '  graph [rankdir=LR, nodesep=0.14, ranksep=0.5, '
        'fontname="Helvetica", fontsize=13, labeljust=l, labelloc=t];',
        '  node [shape=box, fixedsize=true, label=""];',
        '  edge [arrowhead=normal, arrowsize=0.6];']

    def vertex_line(vertex, indent):
        return (f'{indent}{vertex.key} [width='
                f'{vertex.width / POINTS_PER_INCH:.3f}, height='
                f'{vertex.height / POINTS_PER_INCH:.3f}];')
    members = {}
    for vertex in drawing.vertices:
        members.setdefault(vertex.cluster, []).append(vertex)
    for cluster in drawing.clusters:
        lines.append(f'  subgraph cluster_{cluster.key} {{')
        lines.append(f'    label={_quote(cluster.label)};')
        for vertex in members.get(cluster.key, []):
            lines.append(vertex_line(vertex, '    '))
        lines.append('  }')
    for vertex in members.get(None, []):
        lines.append(vertex_line(vertex, '  '))
    for edge in drawing.edges:
        lines.append(f'  {edge.source} -> {edge.target};')
    lines.append('}')
    return '\n'.join(lines) + '\n'


class LayoutError(RuntimeError):
    """dot could not lay out the graph."""


def run_dot_layout(source, executable):
    """The JSON Graphviz writes for the DOT `source`.

    :raises LayoutError: with one sentence saying what went wrong
    """
    try:
        result = subprocess.run(
            [executable, '-Tjson0'], input=source.encode('utf-8'),
            capture_output=True, timeout=DOT_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        raise LayoutError(f'dot did not finish within {DOT_TIMEOUT_S} s')
    except OSError as e:
        raise LayoutError(f'dot could not be run ({e.strerror})')
    if result.returncode != 0:
        message = result.stderr.decode('utf-8', 'replace').strip()
        raise LayoutError(
            f'dot failed ({result.returncode}): '
            f"{message.splitlines()[-1] if message else 'no message'}")
    try:
        return json.loads(result.stdout)
    except ValueError as e:
        raise LayoutError(f'dot wrote JSON that cannot be read ({e})')


def _points(text):
    return [tuple(float(v) for v in p.split(',')) for p in text.split()]


def apply_dot_layout(drawing, layout):
    """Take the positions of Graphviz's JSON (y flipped downwards)."""
    try:
        left, bottom, right, top = (
            float(v) for v in layout['bb'].split(','))
        height = top - bottom
        vertices = {v.key: v for v in drawing.vertices}
        clusters = {f'cluster_{c.key}': c for c in drawing.clusters}
        name_of = {}
        for item in layout.get('objects', []):
            name = item['name']
            if name in clusters:
                x0, y0, x1, y1 = (float(v) for v in item['bb'].split(','))
                cluster = clusters[name]
                cluster.x, cluster.y = x0 - left + MARGIN, top - y1 + MARGIN
                cluster.width, cluster.height = x1 - x0, y1 - y0
            elif name in vertices:
                name_of[item['_gvid']] = name
                x, y = (float(v) for v in item['pos'].split(','))
                vertex = vertices[name]
                vertex.x = x - left - vertex.width / 2 + MARGIN
                vertex.y = top - y - vertex.height / 2 + MARGIN
        edges = {}
        for edge in drawing.edges:
            edges.setdefault((edge.source, edge.target), []).append(edge)
        for item in layout.get('edges', []):
            pair = (name_of[item['tail']], name_of[item['head']])
            edge = edges[pair].pop(0)
            edge.path = _spline_path(
                item['pos'], lambda x, y: (x - left + MARGIN,
                                           top - y + MARGIN))
    except (KeyError, ValueError, IndexError, TypeError) as e:
        raise LayoutError(f'unexpected JSON from dot ({e!r})')
    if any(not e.path for e in drawing.edges):
        raise LayoutError('dot left edges without a route')
    drawing.width = right - left + 2 * MARGIN
    drawing.height = height + 2 * MARGIN
    drawing.engine = 'dot'


def _spline_path(pos, to_page):
    """SVG path data of a Graphviz edge ``pos`` (B-spline, arrow end)."""
    end = None
    start = None
    points = []
    for part in pos.split(';')[0].split():
        if part.startswith('e,'):
            end = _points(part[2:])[0]
        elif part.startswith('s,'):
            start = _points(part[2:])[0]
        else:
            points.append(_points(part)[0])
    points = [to_page(*p) for p in points]
    path = []
    if start is not None:
        x, y = to_page(*start)
        path.append(f'M{_fmt(x)},{_fmt(y)} L{_fmt(points[0][0])},'
                    f'{_fmt(points[0][1])}')
    else:
        path.append(f'M{_fmt(points[0][0])},{_fmt(points[0][1])}')
    for i in range(1, len(points) - 2, 3):
        path.append('C' + ' '.join(
            f'{_fmt(x)},{_fmt(y)}' for x, y in points[i:i + 3]))
    if end is not None:
        x, y = to_page(*end)
        path.append(f'L{_fmt(x)},{_fmt(y)}')
    return ' '.join(path)


# --- the fallback -------------------------------------------------------------

def apply_built_in_layout(drawing):
    """Lay out with the built-in layered layout (top to bottom)."""
    # imported here, as in colcon_rsia.system.graph: only when used
    import networkx as nx
    graph = nx.DiGraph()
    vertex_of = {}
    for vertex in drawing.vertices:
        # (kind, label, key): the layout sorts and sizes by kind and label
        vertex_of[vertex.key] = (vertex.vertex[0], vertex.vertex[1],
                                 vertex.key)
        graph.add_node(vertex_of[vertex.key])
    for edge in drawing.edges:
        graph.add_edge(vertex_of[edge.source], vertex_of[edge.target])
    layout = layered_layout(graph)
    for vertex in drawing.vertices:
        box = layout.boxes[vertex_of[vertex.key]]
        vertex.x, vertex.y, vertex.width = box.x, box.y, box.width
    for edge in drawing.edges:
        source, target = vertex_of[edge.source], vertex_of[edge.target]
        if source == target:
            box = layout.boxes[source]
            edge.path = (f'M{_fmt(box.x)},{_fmt(box.y)} '
                         f'L{_fmt(box.x)},{_fmt(box.y)}')
            continue
        edge.path = _layered_path(
            [layout.boxes[source]] +
            layout.waypoints.get((source, target), []) +
            [layout.boxes[target]])
    drawing.clusters = []
    for vertex in drawing.vertices:
        vertex.cluster = None
    drawing.width, drawing.height = layout.width, layout.height
    drawing.engine = 'built-in'


def _layered_path(boxes):
    """Curves between rows, straight lines through the waypoints."""
    down = boxes[-1].y > boxes[0].y
    points = []
    for index, box in enumerate(boxes):
        top = (box.x + box.width / 2, box.y)
        bottom = (box.x + box.width / 2, box.y + box.height)
        enter, leave = (top, bottom) if down else (bottom, top)
        if index > 0:
            points.append(enter)
        if index < len(boxes) - 1:
            points.append(leave)
    path = [f'M{_fmt(points[0][0])},{_fmt(points[0][1])}']
    for i in range(1, len(points)):
        (x1, y1), (x2, y2) = points[i - 1], points[i]
        if i % 2:
            bend = (y2 - y1) / 2
            path.append(f'C{_fmt(x1)},{_fmt(y1 + bend)} {_fmt(x2)},'
                        f'{_fmt(y2 - bend)} {_fmt(x2)},{_fmt(y2)}')
        else:
            path.append(f'L{_fmt(x2)},{_fmt(y2)}')
    return ' '.join(path)


def draw_system(system, *, dot_executable=None):
    """Lay out the system graph; return (drawing, note or None).

    :param dot_executable: Graphviz ``dot``; default: ``dot`` on PATH
    """
    drawing = plan_drawing(system)
    executable = dot_executable or shutil.which('dot')
    if not executable:
        return _fallback(drawing), f'Graphviz dot is not on PATH: {BUILT_IN}'
    try:
        apply_dot_layout(
            drawing, run_dot_layout(layout_dot_source(drawing), executable))
    except LayoutError as e:
        return _fallback(plan_drawing(system)), f'{e}: {BUILT_IN}'
    return drawing, None


def _fallback(drawing):
    apply_built_in_layout(drawing)
    return drawing
