# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import json
import sys

from colcon_core.logging import colcon_logger
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.safe_files import printable
from colcon_rsia.safe_files import printable_lines
from colcon_rsia.subverb import RsiaSubverbExtensionPoint
from colcon_rsia.subverb.arguments import add_model_argument
from colcon_rsia.subverb.arguments import add_since_argument
from colcon_rsia.subverb.arguments import add_system_arguments
from colcon_rsia.system.impact import expand_changed
from colcon_rsia.system.impact import impact_all
from colcon_rsia.system.impact import impact_to_json
from colcon_rsia.system.impact import UnknownNodeError
from colcon_rsia.system.workspace import load_system_from_args
from colcon_rsia.system.workspace import select_changed
from colcon_rsia.system.workspace import stale_gate_message

logger = colcon_logger.getChild(__name__)

# `impact --fail-on`: the rate-aware impact set holds a listed node
FAIL_ON_EXIT_CODE = 2


class ImpactRsiaSubverb(RsiaSubverbExtensionPoint):
    """Print the nodes whose publishing rate may follow a change."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        add_system_arguments(parser)
        # one of the group is required, checked in main(): argparse's own
        # check would fire in the first pass of colcon-defaults, which
        # parses with the help action suppressed (`impact --help`)
        group = parser.add_mutually_exclusive_group()
        group.add_argument(
            '--changed', nargs='+', metavar='PKG/EXE',
            help='The changed nodes (package/executable, or package/plugin '
                 'for nodelets)')
        add_since_argument(group)
        group.add_argument(
            '--all', action='store_true',
            help='For every node whose change reaches another node: the '
                 'rate-aware and the traditional impact set sizes')
        add_model_argument(parser)
        parser.add_argument(
            '--traditional', action='store_true',
            help='Also list the traditional (data-flow) impact set')
        parser.add_argument(
            '--fail-on', nargs='+', metavar='NODE',
            help='Exit with code 2 (after the normal output) when the '
                 'rate-aware impact set contains any of these nodes '
                 '(names as for --changed)')
        parser.add_argument(
            '--format', choices=('text', 'json'), default='text',
            help='Output format (default: text)')

    def main(self, *, context):  # noqa: D102
        args = context.args
        if not (args.changed or args.since is not None or args.all):
            return 'one of the arguments --changed --since --all is required'
        system, error = load_system_from_args(args, logger)
        if error:
            return error
        if args.all:
            if args.fail_on:
                return '--fail-on needs --changed or --since, not --all'
            result = impact_all(system, args.model)
            if args.format == 'json':
                print(json.dumps(result, indent=2, sort_keys=True))
            else:
                print(_all_text(result), end='')
            return 0
        try:
            fail_on = expand_changed(system, args.fail_on or [])
        except UnknownNodeError as e:
            return printable(f'--fail-on: {e}')
        changed, _, error = select_changed(system, args)
        if error:
            return error
        result = impact_to_json(system, changed, args.model)
        if args.format == 'json':
            print(json.dumps(result, indent=2, sort_keys=True))
        else:
            print(_impact_text(result, args.traditional), end='')
        hit = sorted(set(fail_on) & set(result['rate_impact']))
        if hit:
            sys.stdout.flush()
            print(printable(
                'rsia: the rate-aware impact set contains --fail-on '
                f"node{'s' if len(hit) > 1 else ''} {', '.join(hit)}"),
                file=sys.stderr)
            return FAIL_ON_EXIT_CODE
        stale = stale_gate_message(system, '--fail-on') if args.fail_on \
            else None
        if stale:
            # a gate never passes on results older than the code
            sys.stdout.flush()
            print(stale, file=sys.stderr)
            return FAIL_ON_EXIT_CODE
        return 0


def _impact_text(result, traditional):
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


def _all_text(result):
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
