# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""``summary.md``: a short Markdown summary for a pull-request comment.

No links (a comment has nowhere to link to), no HTML; long lists are cut.
Every value taken from the analysed code (names, ids, file names, a
revision) is data, never Markdown: it goes out as inline code
(:func:`code`) or with every punctuation character escaped (:func:`text`),
on one line, so that a crafted topic or file name cannot add a link, an
image, HTML, emphasis or a heading to the comment.
"""

import re

from colcon_rsia.report import CHANGED
from colcon_rsia.report import RATE
from colcon_rsia.report import TRADITIONAL
from colcon_rsia.safe_files import display

# at most this many rows in a table or items in a list
MAX_ITEMS = 40

STATUS_TEXT = {
    CHANGED: 'changed',
    RATE: 'rate-aware',
    TRADITIONAL: 'traditional only',
}


# a word that no Markdown renderer (GFM, and GitHub's mentions, issue and
# commit references, emoji, math) takes for markup: letters, digits and
# hyphens, maybe in parentheses or before a comma, colon or semicolon
_PLAIN_WORD = re.compile(r'\(?-*[^\W_]+(-+[^\W_]+)*\)?[,;:]?\Z')
# GitHub links a word of 7 or more hex digits to a commit
_COMMIT_LIKE = re.compile(r'\(?[0-9a-fA-F]{7,}')


def _one_line(value):
    """The value as printable text on one line (whitespace runs collapsed)."""
    value = display(str(value))
    value = ''.join(c if c.isprintable() else ' ' for c in value)
    return ' '.join(value.split())


def code(value):
    """Inline code holding any value, backticks included."""
    value = _one_line(value)
    if not value:
        return ''
    fence = '`' * (max(map(len, re.findall('`+', value)), default=0) + 1)
    # a space on each side keeps a backtick at either end off the fence
    # (CommonMark strips one such space on each side)
    pad = ' ' if value[0] == '`' or value[-1] == '`' else ''
    return f'{fence}{pad}{value}{pad}{fence}'


def text(value):
    """Text that Markdown shows as written, and never as markup.

    Plain words stay plain; every other word (a topic, an id, a file name,
    anything with punctuation) goes out as inline code.
    """
    return ' '.join(
        word if _PLAIN_WORD.match(word) and not _COMMIT_LIKE.match(word)
        else code(word) for word in _one_line(value).split(' '))


def cell(value):
    """Markdown (of :func:`code` or :func:`text`) safe in a table cell."""
    return str(value).replace('|', '\\|')


def _cut(items, what):
    if len(items) <= MAX_ITEMS:
        return items, []
    rest = len(items) - MAX_ITEMS
    return items[:MAX_ITEMS], [f'… and {rest} more {what}']


def _plural(count, word):
    return f'{count} {word}{"" if count == 1 else "s"}'


def render_summary(data):
    """The summary.md text."""
    lines = ['### colcon-rsia: rate impact', '']
    if data.impact is None:
        lines += _without_changes(data)
    else:
        lines += _with_changes(data)
    all_impact = data.all_impact
    lines += [
        '',
        f'_colcon-rsia {data.version} · '
        f'{_plural(len(data.system.instances), "node")}, '
        f'{_plural(len(data.graph["topics"]), "topic")} · over all nodes: '
        f'average rate-aware impact {all_impact["average_rate_impact"]:g}, '
        f'traditional {all_impact["average_traditional_impact"]:g} '
        f'(ratio {all_impact["ratio"]:g}; paper model '
        f'{all_impact["paper_ratio"]:g}, trigger model '
        f'{all_impact["trigger_ratio"]:g})_',
    ]
    return '\n'.join(lines) + '\n'


def _without_changes(data):
    lines = ['No changed nodes were given: the impact of each node '
             '(traditional, paper and trigger model impact set sizes).', '']
    rows = data.all_impact['nodes']
    if not rows:
        return lines + ["No node's change reaches another node."]
    lines += ['| node | traditional | paper | trigger |',
              '| --- | ---: | ---: | ---: |']
    shown, more = _cut(rows, 'nodes')
    for row in shown:
        lines.append(f"| {cell(code(row['id']))} | "
                     f"{row['traditional_impact']} | {row['paper_impact']} | "
                     f"{row['trigger_impact']} |")
    return lines + more


def _with_changes(data):
    impact = data.impact
    since = f' since {code(data.since)}' if data.since else ''
    if not data.changed:
        return [f'No analysed node changed{since}: no rate impact.']
    lines = [f'**Changed{since}:** {_plural(len(data.changed), "node")}']
    shown, more = _cut(data.changed, 'nodes')
    for node_id in shown:
        lines.append(
            f'- {code(node_id)}: '
            f"{text('; '.join(data.reasons.get(node_id, [])))}")
    lines += more
    rate = impact['rate_impact']
    traditional = impact['traditional_impact']
    lines += [
        '',
        f'**Rate-aware impact: {_plural(len(rate), "node")}** '
        f'(traditional data-flow impact: {len(traditional)})',
        '']
    affected = list(data.changed) + [n for n in rate if n not in data.changed] \
        + [n for n in traditional if n not in rate and n not in data.changed]
    lines += ['| node | impact | why |', '| --- | --- | --- |']
    shown, more = _cut(affected, 'nodes')
    for node_id in shown:
        status = data.status.get(node_id, '')
        if node_id in data.changed and node_id in rate:
            status_text = 'changed, rate-aware'
        else:
            status_text = STATUS_TEXT.get(status, '')
        why = data.via.get(node_id) if node_id not in data.changed else \
            '; '.join(data.reasons.get(node_id, []))
        lines.append(f'| {cell(code(node_id))} | {cell(text(status_text))} | '
                     f'{cell(text(why or ""))} |')
    lines += more
    if data.stopped:
        lines += ['', '**Stopped at independent edges** (the publisher keeps '
                  'its own rate):']
        shown, more = _cut(data.stopped, 'edges')
        for edge in shown:
            held = ', '.join(code(h) for h in edge.held)
            lines.append(
                f'- {code(edge.topic)} of {code(edge.node)} '
                f"({text(', '.join(edge.patterns))})"
                + (f': holds {held}' if held else ''))
        lines += more
    return lines
