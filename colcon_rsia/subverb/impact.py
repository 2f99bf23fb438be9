# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import json

from colcon_core.logging import colcon_logger
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.impact import expand_changed
from colcon_rsia.impact import impact_all
from colcon_rsia.impact import impact_to_json
from colcon_rsia.impact import UnknownNodeError
from colcon_rsia.subverb import add_system_arguments
from colcon_rsia.subverb import load_system_from_args
from colcon_rsia.subverb import RsiaSubverbExtensionPoint

logger = colcon_logger.getChild(__name__)


class ImpactRsiaSubverb(RsiaSubverbExtensionPoint):
    """Print the nodes whose publishing rate may follow a change."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        add_system_arguments(parser)
        group = parser.add_mutually_exclusive_group(required=True)
        group.add_argument(
            '--changed', nargs='+', metavar='PKG/EXE',
            help='The changed nodes (package/executable, or package/plugin '
                 'for nodelets)')
        group.add_argument(
            '--all', action='store_true',
            help='For every node whose change reaches another node: the '
                 'rate-aware and the traditional impact set sizes')
        parser.add_argument(
            '--traditional', action='store_true',
            help='Also list the traditional (data-flow) impact set')
        parser.add_argument(
            '--format', choices=('text', 'json'), default='text',
            help='Output format (default: text)')

    def main(self, *, context):  # noqa: D102
        args = context.args
        system, error = load_system_from_args(args, logger)
        if error:
            return error
        if args.all:
            result = impact_all(system)
            if args.format == 'json':
                print(json.dumps(result, indent=2, sort_keys=True))
            else:
                print(_all_text(result), end='')
            return 0
        try:
            changed = expand_changed(system, args.changed)
        except UnknownNodeError as e:
            return str(e)
        result = impact_to_json(system, changed)
        if args.format == 'json':
            print(json.dumps(result, indent=2, sort_keys=True))
        else:
            print(_impact_text(result, args.traditional), end='')
        return 0


def _impact_text(result, traditional):
    rate = result['rate_impact']
    data = result['traditional_impact']
    lines = [
        f"changed: {', '.join(result['changed'])}",
        f'rate impact: {len(rate)} nodes; traditional: {len(data)}']
    lines += [f'  {node_id}' for node_id in rate]
    if traditional:
        lines.append('traditional impact:')
        lines += [f'  {node_id}' for node_id in data]
    return '\n'.join(lines) + '\n'


def _all_text(result):
    rows = result['nodes']
    width = max([len(r['id']) for r in rows] + [4])
    lines = [f"{'node':<{width}}  rate  traditional"]
    for row in rows:
        lines.append(
            f"{row['id']:<{width}}  {row['rate_impact']:>4}  "
            f"{row['traditional_impact']:>11}")
    lines.append(
        f"average: rate {result['average_rate_impact']:g}, traditional "
        f"{result['average_traditional_impact']:g}; ratio (rate / "
        f"traditional) {result['ratio']:g} over {len(rows)} nodes")
    return '\n'.join(lines) + '\n'
