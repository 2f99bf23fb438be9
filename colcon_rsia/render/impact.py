# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Impact sets (impact@1) and every node's impact sizes (impact-all@1)."""

from colcon_rsia.render import JSON
from colcon_rsia.render import json_text
from colcon_rsia.safe_files import printable_lines


def render_impact(result, fmt, *, traditional=False):
    """An impact@1 result in format `fmt`.

    :param traditional: the text lists the traditional impact set too
    """
    if fmt == JSON:
        return json_text(result)
    return impact_to_text(result, traditional=traditional)


def render_impact_all(result, fmt):
    """An impact-all@1 result in format `fmt`."""
    if fmt == JSON:
        return json_text(result)
    return impact_all_to_text(result)


def impact_to_text(result, *, traditional=False):
    """The changed nodes, the sizes of the sets, then the nodes of each."""
    rate = result['rate_impact']
    data = result['traditional_impact']
    lines = [
        f"changed: {', '.join(result['changed']) or '(none)'}",
        f"rate impact: {len(rate)} node{'s' if len(rate) != 1 else ''}; "
        f'traditional: {len(data)} '
        f"({result['model']} model; paper {len(result['paper_impact'])}, "
        f"trigger {len(result['trigger_impact'])})"]
    lines += [f'  {node_id}' for node_id in rate]
    if traditional:
        lines.append('traditional impact:')
        lines += [f'  {node_id}' for node_id in data]
    paper_only = sorted(
        set(result['paper_impact']) - set(result['trigger_impact']))
    if paper_only:
        lines.append(f"paper model only: {', '.join(paper_only)}")
    lines += not_triggered_text(result['not_triggered'])
    return printable_lines(lines)


def not_triggered_text(edges):
    """Lines saying where the trigger model stops and the paper's not."""
    lines = []
    if edges:
        lines.append('the trigger model stops at (the paper model crosses):')
    for edge in edges:
        triggers = ', '.join(
            f"{t['trigger']} ({t['evidence']})" for t in edge['triggers'])
        lines.append(
            f"  {edge['node']}: {edge['via']} does not trigger "
            f"{edge['topic']}; triggered by {triggers or 'nothing'}")
    return lines


def impact_all_to_text(result):
    """A table of every node's set sizes, their averages and ratios."""
    rows = result['nodes']
    width = max([len(r['id']) for r in rows] + [4])
    lines = [f"{'node':<{width}}  traditional  paper  trigger"]
    for row in rows:
        lines.append(
            f"{row['id']:<{width}}  {row['traditional_impact']:>11}  "
            f"{row['paper_impact']:>5}  {row['trigger_impact']:>7}")
    lines.append(
        f"average: traditional {result['average_traditional_impact']:g}, "
        f"paper {result['average_paper_impact']:g}, trigger "
        f"{result['average_trigger_impact']:g} over {len(rows)} nodes")
    lines.append(
        f"ratio to traditional: paper {result['paper_ratio']:g}, trigger "
        f"{result['trigger_ratio']:g}; trigger / paper "
        f"{result['trigger_to_paper']:g}")
    for row in rows:
        if row.get('not_triggered'):
            lines.append(f"{row['id']}: trigger {row['trigger_impact']} < "
                         f"paper {row['paper_impact']}:")
            lines += ['  ' + line for line in
                      not_triggered_text(row['not_triggered'])[1:]]
    return printable_lines(lines)
