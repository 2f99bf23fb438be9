# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Predicted rates and what-if answers (rates@1)."""

from colcon_rsia.render import hz_text
from colcon_rsia.render import JSON
from colcon_rsia.render import json_text
from colcon_rsia.safe_files import printable_lines
from colcon_rsia.system.rates import UNKNOWN


def render_rates(result, fmt):
    """A rates@1 result in format `fmt`."""
    if fmt == JSON:
        return json_text(result)
    return rates_to_text(result)


def _hz(hz):
    return hz_text(hz, UNKNOWN)


def rates_to_text(result):
    """Each topic's rate and source; then what changes, and what not."""
    topics = result['topics']
    width = max([len(t['name']) for t in topics] + [5])
    lines = []
    for topic in topics:
        lines.append(f"{topic['name']:<{width}}  {_hz(topic['hz']):>10}  "
                     f"{topic['source']}")
        if topic['hz'] is None and topic['chain']:
            lines.append(f"{'':<{width}}  {'':>10}  ({topic['chain'][-1]})")
    if 'changes' in result:
        lines.append('what if: ' + ', '.join(
            [f'{name}={hz:g} Hz' for name, hz in result['set_rates'].items()]
            + [f'{name} changed' for name in result['changed']]))
        for change in result['changes']:
            to = 'may change' if change['may_change'] else _hz(change['to'])
            lines.append(f"  {change['topic']}: {_hz(change['from'])} -> "
                         + to)
        for keep in result['kept']:
            lines.append(f"  {keep['topic']} keeps {_hz(keep['hz'])}: "
                         f"{keep['edge']} stops {keep['via']}")
    return printable_lines(lines)
