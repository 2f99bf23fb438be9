# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""``index.html``: one self-contained page (inline CSS, JS and SVG only).

Nothing is fetched: a Content-Security-Policy meta tag allows inline styles
and scripts and ``data:`` images, and nothing else. Every text taken from
the summaries is escaped.
"""

from html import escape

from colcon_rsia import model
from colcon_rsia.report import CHANGED
from colcon_rsia.report import edge_patterns
from colcon_rsia.report import RATE
from colcon_rsia.report import TRADITIONAL
from colcon_rsia.report.layout import BOX_HEIGHT
from colcon_rsia.report.layout import layered_layout

CSP = ("default-src 'none'; style-src 'unsafe-inline'; "
       "script-src 'unsafe-inline'; img-src data:")

STATUS_TEXT = {
    CHANGED: 'changed',
    RATE: 'rate-aware impact',
    TRADITIONAL: 'traditional only',
}

STYLE = """
:root { --changed: #219ebc; --rate: #e76f51; --traditional: #e9c46a;
  --ink: #1d1d1f; --muted: #6b6b70; --line: #d7d7db; --stop: #7b2cbf; }
* { box-sizing: border-box; }
body { font: 14px/1.45 "DejaVu Sans", "Helvetica Neue", Arial, sans-serif;
  color: var(--ink); margin: 0 auto; padding: 16px 24px 48px;
  max-width: 1600px; }
h1 { font-size: 22px; margin: 4px 0 2px; }
h2 { font-size: 17px; margin: 28px 0 8px; border-bottom: 1px solid
  var(--line); padding-bottom: 4px; }
.meta, .muted { color: var(--muted); }
code { font: 12px "DejaVu Sans Mono", Menlo, monospace; }
.facts { display: grid; grid-template-columns: max-content 1fr;
  gap: 2px 14px; margin: 10px 0; }
.facts dt { font-weight: bold; }
.facts dd { margin: 0; }
.legend { display: flex; flex-wrap: wrap; gap: 14px; margin: 6px 0;
  font-size: 13px; }
.swatch { display: inline-block; width: 14px; height: 14px;
  border: 1px solid #555; vertical-align: -2px; margin-right: 4px;
  border-radius: 3px; }
.swatch.changed { background: var(--changed); }
.swatch.rate { background: var(--rate); }
.swatch.traditional { background: var(--traditional); }
.swatch.unaffected { background: #fff; }
.swatch.dashed { border: 0; border-top: 2px dashed #555; height: 0;
  width: 22px; vertical-align: 4px; border-radius: 0; }
.scroll { overflow: auto; border: 1px solid var(--line); border-radius: 6px;
  background: #fcfcfd; }
svg text { font: 12px "DejaVu Sans", Arial, sans-serif; fill: var(--ink); }
svg .vertex rect { fill: #fff; stroke: #555; stroke-width: 1.2; }
svg .vertex.topic rect { fill: #f1f1f4; stroke: #888; }
svg .vertex.topic.crossed rect { stroke: var(--rate); stroke-width: 2; }
svg .vertex.changed rect { fill: var(--changed); stroke: #023047;
  stroke-width: 2.5; }
svg .vertex.rate rect { fill: var(--rate); stroke: #8a2d16;
  stroke-width: 2; }
svg .vertex.traditional rect { fill: var(--traditional); }
svg .vertex.dimmed { opacity: 0.2; }
svg .edge { fill: none; stroke: #8a8a90; stroke-width: 1.3; }
svg .edge.independent { stroke-dasharray: 6 4; }
svg .edge.crossed { stroke: var(--rate); stroke-width: 2.2; }
svg .edge.stopped { stroke: var(--stop); stroke-width: 2.2; }
svg .arrow path { fill: #8a8a90; }
svg #arrow-crossed path { fill: var(--rate); }
svg #arrow-stopped path { fill: var(--stop); }
svg .bar.rate { fill: var(--rate); }
svg .bar.traditional { fill: #9aa0a6; }
svg .grid { stroke: #e4e4e8; }
svg .average { stroke-width: 1.5; stroke-dasharray: 5 3; }
svg .average.rate { stroke: var(--rate); }
svg .average.traditional { stroke: #5f6368; }
svg .value { font-size: 10px; fill: var(--muted); }
.filter { position: sticky; top: 0; background: #fff; padding: 8px 0;
  z-index: 2; display: flex; gap: 12px; align-items: center; }
.filter input { font: inherit; padding: 5px 8px; width: 420px;
  border: 1px solid #aaa; border-radius: 4px; }
table { border-collapse: collapse; width: 100%; font-size: 13px; }
th, td { border-bottom: 1px solid var(--line); padding: 4px 8px;
  text-align: left; vertical-align: top; }
th { background: #f4f4f6; position: sticky; top: 46px; }
td ul { margin: 0; padding-left: 16px; }
td.nowrap { white-space: nowrap; }
tr.changed td:first-child { box-shadow: inset 5px 0 var(--changed); }
tr.rate td:first-child { box-shadow: inset 5px 0 var(--rate); }
tr.traditional td:first-child { box-shadow: inset 5px 0 var(--traditional); }
.label-independent { color: #1b7f3b; font-weight: bold; }
.label-dependent { color: #a4161a; font-weight: bold; }
"""

SCRIPT = r"""
(function () {
  'use strict';
  var input = document.getElementById('filter');
  var count = document.getElementById('filter-count');
  var rows = Array.prototype.slice.call(
    document.querySelectorAll('tr[data-filter]'));
  var vertices = Array.prototype.slice.call(
    document.querySelectorAll('#graph g.vertex'));
  var tables = Array.prototype.slice.call(
    document.querySelectorAll('table[data-filterable]'));
  var texts = rows.map(function (row) {
    return row.textContent.toLowerCase();
  });
  function matches(text, words) {
    return words.every(function (word) { return text.indexOf(word) >= 0; });
  }
  function apply() {
    var words = input.value.trim().toLowerCase().split(/\s+/)
      .filter(function (word) { return word.length > 0; });
    var shown = 0;
    rows.forEach(function (row, index) {
      var match = matches(texts[index], words);
      row.hidden = !match;
      if (match) { shown += 1; }
    });
    vertices.forEach(function (vertex) {
      var name = (vertex.getAttribute('data-name') || '').toLowerCase();
      vertex.classList.toggle(
        'dimmed', words.length > 0 && !matches(name, words));
    });
    tables.forEach(function (table) {
      table.setAttribute('data-shown', String(
        table.querySelectorAll('tr[data-filter]:not([hidden])').length));
    });
    count.textContent = shown + ' of ' + rows.length + ' rows';
    document.body.setAttribute('data-shown-rows', String(shown));
  }
  input.addEventListener('input', apply);
  // '#filter=words' in the address fills the box
  var preset = /^#filter=(.*)$/.exec(window.location.hash);
  if (preset) { input.value = decodeURIComponent(preset[1]); }
  apply();
  document.body.setAttribute('data-rows', String(rows.length));
  document.body.setAttribute('data-rendered', 'true');
})();
"""


def _e(text):
    return escape('' if text is None else str(text), quote=True)


def _fmt(number):
    return f'{number:.1f}'.rstrip('0').rstrip('.')


# --- the graph ------------------------------------------------------------

def graph_svg(data):
    """The system graph as inline SVG (no xmlns: it is parsed as HTML)."""
    system = data.system
    layout = layered_layout(system.graph)
    crossed_topics = {t for _, t in data.crossed if t[0] == 'topic'}
    stopped = {(('node', s.node), ('topic', s.topic)) for s in data.stopped}
    width, height = _fmt(layout.width), _fmt(layout.height)
    out = [
        f'<svg id="graph" width="{width}" height="{height}" '
        f'viewBox="0 0 {width} {height}" role="img" '
        'aria-label="system graph: node instances, topics and publisher '
        'edges">',
        '<defs>']
    for name in ('arrow', 'arrow-crossed', 'arrow-stopped'):
        out.append(
            f'<marker id="{name}" class="arrow" viewBox="0 0 10 10" '
            'refX="9" refY="5" markerWidth="8" markerHeight="8" '
            'markerUnits="userSpaceOnUse" orient="auto-start-reverse">'
            '<path d="M0,0 L10,5 L0,10 z"/>'
            '</marker>')
    out.append('</defs>')
    out.append('<g class="edges">')
    for source, target, edge in sorted(system.graph.edges(data=True)):
        out.append(_edge_svg(layout, source, target, edge,
                             (source, target) in data.crossed,
                             (source, target) in stopped))
    out.append('</g><g class="vertices">')
    for vertex in sorted(layout.boxes, key=lambda v: (v[0], v[1])):
        box = layout.boxes[vertex]
        classes = ['vertex', vertex[0]]
        if vertex[0] == 'node':
            status = data.status.get(vertex[1])
            if status:
                classes.append(status)
            tip = f'{vertex[1]}: {STATUS_TEXT.get(status, "unaffected")}'
            radius = BOX_HEIGHT / 2
        else:
            if vertex in crossed_topics:
                classes.append('crossed')
            tip = f'topic {vertex[1]}'
            radius = 3
        out.append(
            f'<g class="{" ".join(classes)}" data-name="{_e(vertex[1])}">'
            f'<title>{_e(tip)}</title>'
            f'<rect x="{_fmt(box.x)}" y="{_fmt(box.y)}" '
            f'width="{_fmt(box.width)}" height="{_fmt(box.height)}" '
            f'rx="{_fmt(radius)}"/>'
            f'<text x="{_fmt(box.x + box.width / 2)}" '
            f'y="{_fmt(box.y + box.height / 2)}" text-anchor="middle" '
            f'dominant-baseline="central">{_e(vertex[1])}</text></g>')
    out.append('</g></svg>')
    return '\n'.join(out)


def _edge_svg(layout, source, target, edge, crossed, stopped):
    boxes = [layout.boxes[source]] + layout.waypoints.get(
        (source, target), []) + [layout.boxes[target]]
    down = boxes[-1].y > boxes[0].y
    # where the edge leaves and enters each box, in drawing order
    points = []
    for index, box in enumerate(boxes):
        top = (box.x + box.width / 2, box.y)
        bottom = (box.x + box.width / 2, box.y + box.height)
        enter, leave = (top, bottom) if down else (bottom, top)
        if index > 0:
            points.append(enter)
        if index < len(boxes) - 1:
            points.append(leave)
    # curves between rows, straight lines through the waypoints
    path = [f'M{_fmt(points[0][0])},{_fmt(points[0][1])}']
    for i in range(1, len(points)):
        (x1, y1), (x2, y2) = points[i - 1], points[i]
        if i % 2:
            bend = (y2 - y1) / 2
            path.append(f'C{_fmt(x1)},{_fmt(y1 + bend)} {_fmt(x2)},'
                        f'{_fmt(y2 - bend)} {_fmt(x2)},{_fmt(y2)}')
        else:
            path.append(f'L{_fmt(x2)},{_fmt(y2)}')
    path = ' '.join(path)
    classes = ['edge']
    marker = 'arrow'
    if source[0] == 'node':
        label = edge.get('label', model.DEPENDENT)
        if label == model.INDEPENDENT:
            classes.append('independent')
        tip = f'{source[1]} publishes {target[1]}: {label} ' \
            f"({', '.join(edge_patterns(edge))})"
    else:
        tip = f'{target[1]} subscribes {source[1]}'
    if crossed:
        classes.append('crossed')
        marker = 'arrow-crossed'
        tip += '; the rate change goes through'
    elif stopped:
        classes.append('stopped')
        marker = 'arrow-stopped'
        tip += '; the rate change stops here'
    return (f'<path class="{" ".join(classes)}" d="{path}" '
            f'marker-end="url(#{marker})"><title>{_e(tip)}</title></path>')


# --- the all-nodes chart (the paper's Fig. 3 and 7) -----------------------

def chart_svg(all_impact):
    """Traditional vs rate-aware impact set size per node, with averages."""
    rows = all_impact['nodes']
    if not rows:
        return ('<p class="muted" id="chart">No node\'s change reaches '
                'another node.</p>')
    label_width = 16 + 7 * max(len(r['id']) for r in rows)
    plot = 480.0
    top = 44.0
    row_height = 30.0
    bar = 10.0
    largest = max(max(r['traditional_impact'], r['rate_impact'])
                  for r in rows) or 1
    scale = plot / largest
    width = label_width + plot + 190
    height = top + row_height * len(rows) + 26
    out = [f'<svg id="chart" width="{_fmt(width)}" height="{_fmt(height)}" '
           f'viewBox="0 0 {_fmt(width)} {_fmt(height)}" role="img" '
           'aria-label="impact set size per changed node">']
    # legend
    out.append(
        '<rect class="bar traditional" x="0" y="4" width="12" height="12"/>'
        '<text x="18" y="14">traditional</text>'
        '<rect class="bar rate" x="110" y="4" width="12" height="12"/>'
        '<text x="128" y="14">rate-aware</text>')
    step = max(1, -(-largest // 10))
    for tick in range(0, largest + 1, step):
        x = label_width + tick * scale
        out.append(
            f'<line class="grid" x1="{_fmt(x)}" y1="{_fmt(top - 6)}" '
            f'x2="{_fmt(x)}" y2="{_fmt(height - 22)}"/>'
            f'<text class="value" x="{_fmt(x)}" y="{_fmt(height - 8)}" '
            f'text-anchor="middle">{tick}</text>')
    for index, row in enumerate(rows):
        y = top + index * row_height
        out.append(
            f'<g class="chart-row" data-name="{_e(row["id"])}">'
            f'<text x="{_fmt(label_width - 8)}" y="{_fmt(y + bar)}" '
            f'text-anchor="end" dominant-baseline="central">'
            f'{_e(row["id"])}</text>')
        for offset, kind in ((0, 'traditional'), (bar + 1, 'rate')):
            value = row[f'{kind}_impact']
            out.append(
                f'<rect class="bar {kind}" x="{_fmt(label_width)}" '
                f'y="{_fmt(y + offset)}" width="{_fmt(value * scale)}" '
                f'height="{_fmt(bar)}"><title>{_e(row["id"])}: {kind} '
                f'impact {value}</title></rect>'
                f'<text class="value" x="{_fmt(label_width + value * scale + 4)}" '
                f'y="{_fmt(y + offset + bar / 2)}" '
                f'dominant-baseline="central">{value}</text>')
        out.append('</g>')
    for kind, dy in (('traditional', 0), ('rate', 14)):
        average = all_impact[f'average_{kind}_impact']
        x = label_width + average * scale
        out.append(
            f'<line class="average {kind}" x1="{_fmt(x)}" y1="{_fmt(top - 8)}" '
            f'x2="{_fmt(x)}" y2="{_fmt(height - 22)}"/>'
            f'<text class="value" x="{_fmt(x + 3)}" y="{_fmt(top - 16 + dy - 8)}">'
            f'average {kind} {average:g}</text>')
    out.append('</svg>')
    return '\n'.join(out)


# --- tables ----------------------------------------------------------------

def _status_cell(status):
    return _e(STATUS_TEXT.get(status, ''))


def node_table(data):
    """One row per publisher (one for a node publishing nothing)."""
    out = ['<table id="nodes" data-filterable="nodes"><thead><tr>'
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
                f'<td class="nowrap">{_e(rate)}</td>'
                f'<td><ul>{"".join(evidence)}</ul></td></tr>')
    out.append('</tbody></table>')
    return '\n'.join(out)


def topic_table(data):
    """One row per topic: who publishes it (with the label), who reads it."""
    graph = data.system.graph
    out = ['<table id="topics" data-filterable="topics"><thead><tr>'
           '<th>topic</th><th>publishers</th><th>subscribers</th></tr>'
           '</thead><tbody>']
    for topic in data.graph['topics']:
        vertex = ('topic', topic['name'])
        publishers = []
        for node_id in topic['publishers']:
            label = graph.edges[('node', node_id), vertex].get(
                'label', model.DEPENDENT)
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


def render_html(data):
    """The whole page."""
    all_impact = data.all_impact
    notes = ''.join(f'<li>{_e(n)}</li>' for n in data.notes)
    notes = f'<h2>Notes</h2><ul id="notes">{notes}</ul>' if notes else ''
    nodes = len(data.system.instances)
    topics = len(data.graph['topics'])
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="{_e(CSP)}">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="colcon-rsia {_e(data.version)}">
<link rel="icon" href="data:,">
<title>colcon-rsia report</title>
<style>{STYLE}</style>
</head>
<body>
<h1>Rate impact report</h1>
<p class="meta">colcon-rsia {_e(data.version)} &middot; {nodes} node
instance{'' if nodes == 1 else 's'}, {topics} topic{'' if topics == 1 else 's'}</p>
{_impact_section(data)}
<h2>System graph</h2>
<div class="legend">
<span><i class="swatch changed"></i>changed</span>
<span><i class="swatch rate"></i>rate-aware impact</span>
<span><i class="swatch traditional"></i>traditional impact only</span>
<span><i class="swatch unaffected"></i>unaffected node</span>
<span><i class="swatch dashed"></i>independent edge</span>
<span class="muted">rounded: node &middot; square: topic &middot; red edges: the
rate change propagates &middot; purple: it stops at an independent edge</span>
</div>
<div class="scroll">{graph_svg(data)}</div>
<h2>Impact of each node (the paper's Fig. 3 and 7)</h2>
<p class="meta">For every node whose change reaches another node: the size of
its traditional and its rate-aware impact set. Averages: traditional
{all_impact['average_traditional_impact']:g}, rate-aware
{all_impact['average_rate_impact']:g}; ratio (rate-aware / traditional)
{all_impact['ratio']:g} ({all_impact['model']} model). Paper model: average
{all_impact['average_paper_impact']:g}, ratio {all_impact['paper_ratio']:g};
trigger model: average {all_impact['average_trigger_impact']:g}, ratio
{all_impact['trigger_ratio']:g}.</p>
<div class="scroll">{chart_svg(all_impact)}</div>
<div class="filter"><label for="filter">Filter</label>
<input id="filter" type="search" placeholder="node, topic, label, file…"
autocomplete="off"><span id="filter-count" class="muted"></span></div>
<h2>Nodes and their publishers</h2>
{node_table(data)}
<h2>Topics</h2>
{topic_table(data)}
{notes}
<script>{SCRIPT}</script>
</body>
</html>
"""
