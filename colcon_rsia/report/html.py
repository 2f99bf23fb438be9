# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""``index.html``: one self-contained page (inline CSS, JS and SVG only).

Nothing is fetched: a Content-Security-Policy meta tag allows inline styles
and scripts and ``data:`` images, and nothing else. Every text taken from
the summaries is escaped.
"""

from html import escape
import json
import os

from colcon_rsia.report import CHANGED
from colcon_rsia.report import RATE
from colcon_rsia.report import TRADITIONAL
from colcon_rsia.report.layout import BOX_HEIGHT
from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import INDEPENDENT

CSP = ("default-src 'none'; style-src 'unsafe-inline'; "
       "script-src 'unsafe-inline'; img-src data:")

STATUS_TEXT = {
    CHANGED: 'changed',
    RATE: 'rate-aware impact',
    TRADITIONAL: 'traditional only',
}

ASSETS = os.path.dirname(os.path.abspath(__file__))


def _asset(name):
    with open(os.path.join(ASSETS, name), encoding='utf-8') as h:
        return h.read()


def _e(text):
    return escape('' if text is None else str(text), quote=True)


def _fmt(number):
    return f'{number:.1f}'.rstrip('0').rstrip('.')


# --- the graph ------------------------------------------------------------

ARROWS = ('arrow', 'arrow-crossed', 'arrow-stopped')


def _json_for_script(value):
    """JSON safe inside a ``<script type="application/json">`` element."""
    return json.dumps(value, separators=(',', ':'), sort_keys=True) \
        .replace('<', '\\u003c').replace('>', '\\u003e') \
        .replace('&', '\\u0026')


def graph_data(data):
    """What the evidence panel shows, by node id and topic name."""
    nodes = {}
    for instance in data.system.instances.values():
        why = data.via.get(instance.id) or \
            '; '.join(data.reasons.get(instance.id, []))
        nodes[instance.id] = {
            'status': data.status.get(instance.id, ''),
            'why': why,
            'exe': f'{instance.package}/{instance.executable}',
            'fqn': instance.fqn,
            'analysed': instance.node is not None,
            'pub': [[
                entry['resolved'] or f"{entry['publisher'].topic} "
                '(not resolved)',
                entry['publisher'].label, entry['publisher'].pattern,
                entry['publisher'].rate_hz, entry['publisher'].location,
                [[e.kind, e.location, e.detail]
                 for e in entry['publisher'].evidence]]
                for entry in instance.publishers],
            'sub': [[
                entry['resolved'] or f"{entry['subscriber'].topic} "
                '(not resolved)',
                entry['subscriber'].location, entry['subscriber'].callback]
                for entry in instance.subscribers],
        }
    graph = data.system.graph
    topics = {}
    for topic in data.graph['topics']:
        vertex = ('topic', topic['name'])
        topics[topic['name']] = {
            'pub': [[p, graph.edges[('node', p), vertex].get(
                'label', DEPENDENT)] for p in topic['publishers']],
            'sub': topic['subscribers'],
        }
    return {'nodes': nodes, 'topics': topics}


def _svg_style():
    """The rules of page.css between ``graph.svg: begin`` and ``end``."""
    css = _asset('page.css')
    parts = []
    for chunk in css.split('/* graph.svg: begin */')[1:]:
        parts.append(chunk.split('/* graph.svg: end */')[0].strip())
    return '\n'.join(parts)


def graph_svg(data, drawing, *, standalone=False):
    """The system graph as SVG.

    Inline in the page it has no xmlns (it is parsed as HTML) and fills its
    box; `standalone` (graph.svg) adds the namespace, its size and its
    style. With changed nodes, what the change does not reach carries the
    class ``faded`` (dimmed while the impact focus is on).
    """
    focus = data.changed is not None
    crossed_topics = {t for _, t in data.crossed if t[0] == 'topic'}
    stopped_edges = {(('node', s.node), ('topic', s.topic))
                     for s in data.stopped}
    stopped_topics = {('topic', s.topic) for s in data.stopped}
    width, height = _fmt(drawing.width), _fmt(drawing.height)
    size = ''
    if standalone:
        size = (f'xmlns="http://www.w3.org/2000/svg" width="{width}" '
                f'height="{height}" viewBox="0 0 {width} {height}" ')
    out = [
        f'<svg id="graph" {size}class="{"focus" if focus else ""}" '
        f'data-width="{width}" data-height="{height}" '
        f'data-layout="{_e(drawing.engine)}" role="img" '
        'aria-label="system graph: node instances, topics and publisher '
        'edges">']
    if standalone:
        out.append(f'<style>{_svg_style()}</style>')
    out.append('<defs>')
    for name in ARROWS:
        out.append(
            f'<marker id="{name}" class="arrow" viewBox="0 0 10 10" '
            'refX="10" refY="5" markerWidth="8" markerHeight="8" '
            'markerUnits="userSpaceOnUse" orient="auto-start-reverse">'
            '<path d="M0,0 L10,5 L0,10 z"/>'
            '</marker>')
    out.append('</defs><g id="graph-view">')
    out.append('<g class="clusters">')
    for cluster in drawing.clusters:
        out.append(
            f'<g class="cluster" data-cluster="{cluster.key}">'
            f'<rect x="{_fmt(cluster.x)}" y="{_fmt(cluster.y)}" '
            f'width="{_fmt(cluster.width)}" height="{_fmt(cluster.height)}" '
            f'rx="6"/><text x="{_fmt(cluster.x + 8)}" '
            f'y="{_fmt(cluster.y + 15)}">{_e(cluster.label)}'
            f'<title>click: hide or show its {len(cluster.members)} '
            'boxes</title></text></g>')
    out.append('</g><g class="edges">')
    for index, edge in enumerate(drawing.edges):
        source, target = edge.edge
        classes = ['edge']
        if source[0] == 'node' and data.system.graph.edges[edge.edge].get(
                'label', DEPENDENT) == INDEPENDENT:
            classes.append('independent')
        marker = 'arrow'
        if edge.edge in data.crossed:
            classes.append('crossed')
            marker = 'arrow-crossed'
        elif edge.edge in stopped_edges:
            classes.append('stopped')
            marker = 'arrow-stopped'
        elif focus:
            classes.append('faded')
        out.append(
            f'<path class="{" ".join(classes)}" data-key="e{index}" '
            f'data-source="{edge.source}" data-target="{edge.target}" '
            f'd="{edge.path}" marker-end="url(#{marker})"/>')
    out.append('</g><g class="vertices">')
    for vertex in drawing.vertices:
        kind, name = vertex.vertex
        classes = ['vertex', kind]
        if kind == 'node':
            status = data.status.get(name)
            if status:
                classes.append(status)
            elif focus:
                classes.append('faded')
            tip = f'{name}: {STATUS_TEXT.get(status, "unaffected")}'
            radius = BOX_HEIGHT / 2
        else:
            if vertex.vertex in crossed_topics:
                classes.append('crossed')
            elif vertex.vertex in stopped_topics:
                classes.append('stopped')
            elif focus:
                classes.append('faded')
            tip = f'topic {name}'
            if vertex.copies > 1:
                tip += f' (hub: drawn in {vertex.copies} clusters)'
            radius = 3
        attributes = ''
        if vertex.cluster is not None:
            attributes += f' data-cluster="{vertex.cluster}"'
        if vertex.copies > 1:
            attributes += f' data-copies="{vertex.copies}"'
        out.append(
            f'<g class="{" ".join(classes)}" data-name="{_e(name)}" '
            f'data-key="{vertex.key}"{attributes}>'
            f'<title>{_e(tip)}</title>'
            f'<rect x="{_fmt(vertex.x)}" y="{_fmt(vertex.y)}" '
            f'width="{_fmt(vertex.width)}" height="{_fmt(vertex.height)}" '
            f'rx="{_fmt(radius)}"/>'
            f'<text x="{_fmt(vertex.x + vertex.width / 2)}" '
            f'y="{_fmt(vertex.y + vertex.height / 2)}" text-anchor="middle" '
            f'dominant-baseline="central">{_e(name)}</text></g>')
    out.append('</g></g></svg>')
    return '\n'.join(out)


def graph_section(data, drawing):
    """The tools, the graph view, the evidence panel and their data."""
    focus = ''
    if data.changed is not None:
        focus = ('<button id="focus-impact" type="button" aria-pressed="true"'
                 ' title="dim what the change does not reach">impact focus'
                 '</button>')
    # a small graph gets a box no higher than it needs
    box_height = max(300.0, drawing.height + 40)
    collapse = ''
    if drawing.clusters:
        collapse = ('<button id="collapse-all" type="button" '
                    'aria-pressed="false">collapse clusters</button>')
    return f"""<div class="graph-tools">
<input id="graph-search" type="search" placeholder="find a node or topic (Enter: next)"
autocomplete="off" aria-label="find a node or topic">
<span id="graph-found" class="muted"></span>
<button id="zoom-in" type="button" title="zoom in">+</button>
<button id="zoom-out" type="button" title="zoom out">&minus;</button>
<button id="zoom-fit" type="button" title="show the whole graph">fit</button>
{focus}{collapse}
<span class="muted">drag: pan &middot; wheel: zoom &middot; click a box or an
edge: its evidence &middot; click a cluster's name: hide or show it</span>
</div>
<div class="graph-main">
<div id="graph-box" style="height: min(70vh, {_fmt(box_height)}px)">
{graph_svg(data, drawing)}</div>
<aside class="graph-side"><div id="graph-panel" aria-live="polite">
<p class="muted">Click a node, a topic or an edge to see its evidence
(<code>file:line</code>).</p></div></aside>
</div>
<script type="application/json" id="graph-data">{_json_for_script(graph_data(data))}</script>"""


# --- the impact of every node (the paper's Fig. 3 and 7) -------------------

def impact_table(all_impact):
    """Traditional vs rate-aware impact set size per node, as bars."""
    rows = all_impact['nodes']
    if not rows:
        return ('<p class="muted" id="all-impact">No node\'s change reaches '
                'another node.</p>')
    largest = max(max(r['traditional_impact'], r['rate_impact'])
                  for r in rows) or 1
    out = ['<table id="all-impact" class="sortable" '
           'data-filterable="impact"><thead><tr><th>changed node</th>'
           '<th>traditional</th><th>rate-aware</th>'
           '<th>rate-aware / traditional</th><th>sizes</th></tr></thead>'
           '<tbody>']
    for row in rows:
        traditional, rate = row['traditional_impact'], row['rate_impact']
        ratio = rate / traditional if traditional else 1.0
        out.append(
            f'<tr data-filter="impact"><td><code>{_e(row["id"])}</code></td>'
            f'<td class="number">{traditional}</td>'
            f'<td class="number">{rate}</td>'
            f'<td class="number">{ratio:.2f}</td>'
            f'<td class="bars" data-sort="{rate}">'
            f'<span class="bar traditional" style="width: '
            f'{100 * traditional / largest:.1f}%"></span>'
            f'<span class="bar rate" style="width: '
            f'{100 * rate / largest:.1f}%"></span></td></tr>')
    out.append('</tbody></table>')
    return '\n'.join(out)


# --- tables ----------------------------------------------------------------

def _status_cell(status):
    return _e(STATUS_TEXT.get(status, ''))


def node_table(data):
    """One row per publisher (one for a node publishing nothing)."""
    out = ['<table id="nodes" class="sortable" data-filterable="nodes"><thead><tr>'
           '<th>node</th><th>impact</th><th>topic</th><th>label</th>'
           '<th>pattern</th><th>rate</th><th>evidence</th></tr></thead>'
           '<tbody>']
    for instance in sorted(data.system.instances.values(),
                           key=lambda i: i.id):
        status = data.status.get(instance.id, '')
        node_cell = f'<td><code>{_e(instance.id)}</code>'
        if instance.id != f'{instance.package}/{instance.executable}':
            node_cell += (f'<br><span class="muted">{_e(instance.package)}/'
                          f'{_e(instance.executable)}</span>')
        node_cell += '</td>'
        why = data.via.get(instance.id) or \
            '; '.join(data.reasons.get(instance.id, []))
        status_cell = f'<td>{_status_cell(status)}'
        if why:
            status_cell += f'<br><span class="muted">{_e(why)}</span>'
        status_cell += '</td>'
        row_open = f'<tr class="{_e(status)}" data-filter="node">'
        if not instance.publishers:
            note = 'publishes nothing'
            if instance.node is None:
                note = ('not analysed: assumed to read and write its '
                        'remapped topics')
            out.append(f'{row_open}{node_cell}{status_cell}'
                       f'<td colspan="5" class="muted">{_e(note)}</td></tr>')
            continue
        for entry in instance.publishers:
            publisher = entry['publisher']
            topic = entry['resolved'] or f'{publisher.topic} (not resolved)'
            rate = f'{publisher.rate_hz:g} Hz' if publisher.rate_hz else ''
            evidence = [
                f'<li><code>{_e(publisher.location)}</code> advertised '
                f'({_e(publisher.api)})</li>']
            evidence += [
                f'<li><code>{_e(e.location)}</code> {_e(e.kind)}'
                + (f': {_e(e.detail)}' if e.detail else '') + '</li>'
                for e in publisher.evidence]
            out.append(
                f'{row_open}{node_cell}{status_cell}'
                f'<td><code>{_e(topic)}</code></td>'
                f'<td class="nowrap label-{_e(publisher.label)}">'
                f'{_e(publisher.label)}</td>'
                f'<td class="nowrap">{_e(publisher.pattern)}</td>'
                f'<td class="nowrap" data-sort="{publisher.rate_hz or 0:g}">'
                f'{_e(rate)}</td>'
                f'<td><ul>{"".join(evidence)}</ul></td></tr>')
    out.append('</tbody></table>')
    return '\n'.join(out)


def topic_table(data):
    """One row per topic: who publishes it (with the label), who reads it."""
    graph = data.system.graph
    out = ['<table id="topics" class="sortable" data-filterable="topics"><thead><tr>'
           '<th>topic</th><th>publishers</th><th>subscribers</th></tr>'
           '</thead><tbody>']
    for topic in data.graph['topics']:
        vertex = ('topic', topic['name'])
        publishers = []
        for node_id in topic['publishers']:
            label = graph.edges[('node', node_id), vertex].get(
                'label', DEPENDENT)
            publishers.append(
                f'<li><code>{_e(node_id)}</code> '
                f'<span class="label-{_e(label)}">{_e(label)}</span></li>')
        subscribers = [f'<li><code>{_e(s)}</code></li>'
                       for s in topic['subscribers']]
        out.append(
            f'<tr data-filter="topic"><td><code>{_e(topic["name"])}</code>'
            f'</td><td><ul>{"".join(publishers)}</ul></td>'
            f'<td><ul>{"".join(subscribers)}</ul></td></tr>')
    out.append('</tbody></table>')
    return '\n'.join(out)


# --- the page ----------------------------------------------------------------

def _impact_section(data):
    if data.impact is None:
        return ('<p class="muted">No changed nodes were given (use '
                '<code>--changed</code> or <code>--since</code>): the graph '
                'shows no impact.</p>')
    rate = data.impact['rate_impact']
    traditional = data.impact['traditional_impact']
    source = f' since <code>{_e(data.since)}</code>' if data.since else ''
    changed = ''.join(
        f'<li><code>{_e(c)}</code>: {_e("; ".join(data.reasons[c]))}</li>'
        for c in data.changed) or '<li class="muted">none</li>'
    rate_items = ''.join(
        f'<li><code>{_e(n)}</code> <span class="muted">'
        f'{_e(data.via.get(n, ""))}</span></li>' for n in rate) or \
        '<li class="muted">none</li>'
    stopped = ''.join(
        f'<li><code>{_e(s.topic)}</code> of <code>{_e(s.node)}</code> '
        f'({_e(", ".join(s.patterns))}) &rarr; '
        f'{_e(", ".join(s.subscribers))}</li>' for s in data.stopped) or \
        '<li class="muted">none</li>'
    return (
        f'<dl class="facts" id="impact">'
        f'<dt>changed{source}</dt><dd><ul>{changed}</ul></dd>'
        f'<dt>rate-aware impact</dt><dd><strong>{len(rate)}</strong> '
        f'node{"" if len(rate) == 1 else "s"} <span class="muted">'
        f'(traditional: {len(traditional)})</span><ul>{rate_items}</ul></dd>'
        f'<dt>stopped at</dt><dd><ul>{stopped}</ul></dd></dl>')


def render_html(data, drawing=None):
    """The whole page.

    :param drawing: the laid out system graph; default: laid out here
      (:func:`colcon_rsia.report.drawing.draw_system`)
    """
    if drawing is None:
        from colcon_rsia.report.drawing import draw_system
        drawing, _ = draw_system(data.system)
    all_impact = data.all_impact
    notes = ''.join(f'<li>{_e(n)}</li>' for n in data.notes)
    notes = f'<h2>Notes</h2><ul id="notes">{notes}</ul>' if notes else ''
    nodes = len(data.system.instances)
    topics = len(data.graph['topics'])
    layout = 'Graphviz dot' if drawing.engine == 'dot' else \
        'the built-in layered layout (Graphviz dot was not available)'
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="{_e(CSP)}">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="colcon-rsia {_e(data.version)}">
<link rel="icon" href="data:,">
<title>colcon-rsia report</title>
<style>{_asset('page.css')}</style>
</head>
<body>
<h1>Rate impact report</h1>
<p class="meta">colcon-rsia {_e(data.version)} &middot; {nodes} node
instance{'' if nodes == 1 else 's'}, {topics} topic{'' if topics == 1 else 's'}</p>
<h2>System graph</h2>
<div class="legend">
<span><i class="swatch changed"></i>changed</span>
<span><i class="swatch rate"></i>rate-aware impact</span>
<span><i class="swatch traditional"></i>traditional impact only</span>
<span><i class="swatch unaffected"></i>unaffected node</span>
<span><i class="swatch dashed"></i>independent edge</span>
<span><i class="swatch stopped"></i>the rate change stops here</span>
<span class="muted">rounded: node &middot; square: topic &middot; red edges: the
rate change propagates &middot; laid out by {layout}</span>
</div>
{graph_section(data, drawing)}
<h2>Impact</h2>
{_impact_section(data)}
<div class="filter"><label for="filter">Filter the tables</label>
<input id="filter" type="search" placeholder="node, topic, label, file…"
autocomplete="off"><span id="filter-count" class="muted"></span>
<span class="muted">click a column's name to sort</span></div>
<h2>Impact of each node (the paper's Fig. 3 and 7)</h2>
<p class="meta">For every node whose change reaches another node: the size of
its traditional and its rate-aware impact set. Averages: traditional
{all_impact['average_traditional_impact']:g}, rate-aware
{all_impact['average_rate_impact']:g}; ratio (rate-aware / traditional)
{all_impact['ratio']:g} ({all_impact['model']} model). Paper model: average
{all_impact['average_paper_impact']:g}, ratio {all_impact['paper_ratio']:g};
trigger model: average {all_impact['average_trigger_impact']:g}, ratio
{all_impact['trigger_ratio']:g}.</p>
{impact_table(all_impact)}
<h2>Nodes and their publishers</h2>
{node_table(data)}
<h2>Topics</h2>
{topic_table(data)}
{notes}
<script>{_asset('page.js')}</script>
</body>
</html>
"""
