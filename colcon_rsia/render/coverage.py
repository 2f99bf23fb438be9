# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the analysis understood of each package (coverage@1).

The renderers read the document by the names docs/json.md gives its keys
and values; the build-time code that computes it is never imported here.
"""

from colcon_rsia.render import JSON
from colcon_rsia.render import json_text
from colcon_rsia.safe_files import printable
from colcon_rsia.safe_files import printable_lines

# keys of ``call_sites`` and the status of an analysed package in the
# coverage@1 document
PUBLISHER = 'publisher'
SUBSCRIBER = 'subscriber'
ANALYSED = 'analysed'


def render_coverage(report, fmt, *, missed=False, repairs=False):
    """A coverage@1 report in format `fmt`.

    :param missed: the text lists each call site without a fact
    :param repairs: the text lists each repair of the model mode
    """
    if fmt == JSON:
        return json_text(report)
    return coverage_to_text(report, missed=missed, repairs=repairs)


def total_line(report):
    """One line: the workspace total (the end of ``analyze``)."""
    total = report['total']
    pub = total['call_sites'][PUBLISHER]
    sub = total['call_sites'][SUBSCRIBER]
    outside = pub['in_units_only'] + sub['in_units_only']
    tokens = pub.get('from_tokens', 0) + sub.get('from_tokens', 0)
    return printable(
        f"rsia: coverage {total['percent']:.1f}% of "
        f"{pub['sites'] + sub['sites']} publisher/subscription call sites "
        f'in a node ({_fraction(pub)} publishers, {_fraction(sub)} '
        'subscriptions' +
        (f'; {outside} more only in code no node runs' if outside else '') +
        (f'; {tokens} read from tokens where the parse failed'
         if tokens else '') +
        f"); {total['units_with_errors']} of "
        f"{total['units']} translation units with errors in package code" +
        (f" ({total.get('units_losing_calls', 0)} of them losing calls)"
         if total['units_with_errors'] else '') + '; ' +
        f"{total['failed']} packages failed; see 'colcon rsia coverage'")


def _fraction(counts):
    return f"{counts['in_nodes']}/{counts['sites']}"


def coverage_to_text(report, *, missed=False, repairs=False):
    """The report as a table, one package a line, then the total.

    :param missed: list each call site without a fact
    :param repairs: list each repair of the model mode, with its rule
    """
    lines = [f"{'package':<40} {'units':>6} {'errors':>6} {'lost':>6} "
             f"{'pub':>9} {'sub':>9} {'unres.':>6} {'unnamed':>7}"]
    for p in report['packages']:
        if p['status'] != ANALYSED:
            why = f": {p['error']}" if p.get('error') else ''
            lines.append(f"{p['package']:<40} {p['status']}{why}")
            continue
        calls = p['call_sites']
        lines.append(
            f"{p['package']:<40} {p['units']:>6} {p['units_with_errors']:>6} "
            f"{p.get('units_losing_calls', 0):>6} "
            f'{_fraction(calls[PUBLISHER]):>9} '
            f'{_fraction(calls[SUBSCRIBER]):>9} '
            f"{len(p['unresolved_topics']):>6} {len(p['unnamed_nodes']):>7}"
            + ('' if p['has_coverage'] else '  (re-analyse: no coverage)'))
        if missed:
            lines += [f"  missed {m['role']}: {m['file']}:{m['line']} "
                      f"({m['api']})" for m in p['missed']]
        if repairs:
            lines += [f"  repair {r['rule']}: {r['kind']} {r['name']} "
                      f"({r['file']})" for r in p.get('repairs', ())]
    if repairs:
        counts = report['total'].get('repairs', {})
        lines.append('repairs by rule: ' + (', '.join(
            f'{rule} {count}' for rule, count in counts.items()) or 'none'))
    lines.append(total_line(report))
    return printable_lines(lines)
