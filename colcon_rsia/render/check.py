# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Recordings against the predictions (check@1)."""

from colcon_rsia.render import hz_text
from colcon_rsia.render import JSON
from colcon_rsia.render import json_text
from colcon_rsia.safe_files import printable_lines


def render_check(result, fmt):
    """A check@1 result in format `fmt`."""
    if fmt == JSON:
        return json_text(result)
    return check_to_text(result)


def _hz(hz):
    return hz_text(hz, '-')


def check_to_text(result):
    """Each topic measured and predicted, the counts, then the misses."""
    two = result['changed'] is not None
    width = max([len(t['name']) for t in result['topics']] + [5])
    lines = []
    for topic in result['topics']:
        measured = _hz(topic['before_hz'])
        if two:
            measured += f" -> {_hz(topic['after_hz'])}"
        may = ' (predicted: may change)' \
            if topic.get('predicted_to_change') else ''
        lines.append(f"{topic['name']:<{width}}  {measured:>20}  "
                     f"predicted {_hz(topic['predicted_hz']):>10}  "
                     f"{topic['status']}{may}")
    lines.append(', '.join(
        f'{count} {status}' for status, count in result['counts'].items())
        + f" (tolerance {result['tolerance']:.0%})")
    if two:
        lines.append(f"changed: {', '.join(result['changed']) or '(none)'} "
                     f"({result['model']} model)")
        for miss in result['unexpected_changes']:
            kept = '; '.join(miss['kept_by']) or \
                'no edge of the model reaches it'
            lines.append(f"  unexpected change of {miss['topic']}: "
                         f"{_hz(miss['before_hz'])} -> "
                         f"{_hz(miss['after_hz'])} ({kept})")
        for topic in result['changes_outside_the_model']:
            lines.append(f"  changed outside the model: {topic['topic']} "
                         f"({_hz(topic['before_hz'])} -> "
                         f"{_hz(topic['after_hz'])}; no analysed node "
                         'publishes it)')
        for topic in result['predicted_but_unchanged']:
            lines.append(f'  predicted to change, unchanged: '
                         f"{topic['topic']} ({_hz(topic['after_hz'])})")
    return printable_lines(lines)
