# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import sys

from colcon_core.logging import colcon_logger
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.render.impact import render_impact
from colcon_rsia.render.impact import render_impact_all
from colcon_rsia.safe_files import printable
from colcon_rsia.subverb import RsiaSubverbExtensionPoint
from colcon_rsia.subverb.arguments import add_format_argument
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
        add_format_argument(parser)

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
            print(render_impact_all(result, args.format), end='')
            return 0
        try:
            fail_on = expand_changed(system, args.fail_on or [])
        except UnknownNodeError as e:
            return printable(f'--fail-on: {e}')
        changed, _, error = select_changed(system, args)
        if error:
            return error
        result = impact_to_json(system, changed, args.model)
        print(render_impact(result, args.format,
                            traditional=args.traditional), end='')
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
