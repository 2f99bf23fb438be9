# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import sys

from colcon_core.logging import colcon_logger
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.safe_files import printable
from colcon_rsia.subverb import RsiaSubverbExtensionPoint
from colcon_rsia.subverb.arguments import add_format_argument
from colcon_rsia.subverb.arguments import add_model_argument
from colcon_rsia.subverb.arguments import add_since_argument
from colcon_rsia.subverb.arguments import add_system_arguments
from colcon_rsia.system.workspace import load_system_from_args
from colcon_rsia.system.workspace import select_changed
from colcon_rsia.system.workspace import stale_gate_message

logger = colcon_logger.getChild(__name__)

# `check --fail-on-unexpected`: a measured change the model did not predict
UNEXPECTED_EXIT_CODE = 2


class CheckRsiaSubverb(RsiaSubverbExtensionPoint):
    """Compare the predicted rates with the rates recorded in bags."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        add_system_arguments(parser)
        parser.add_argument(
            '--bag', action='append', required=True, metavar='PATH',
            help='A recording (ROS 1 .bag file, ROS 2 bag directory with '
                 'sqlite3 or MCAP storage); give it twice, before then '
                 'after a change, to check the predicted impact')
        group = parser.add_mutually_exclusive_group()
        group.add_argument(
            '--changed', nargs='+', metavar='PKG/EXE',
            help='With two bags: the nodes changed between them')
        add_since_argument(group)
        add_model_argument(parser)
        parser.add_argument(
            '--tolerance', type=float, default=None, metavar='FRACTION',
            help='Relative difference of two rates still taken as equal '
                 '(default: 0.15)')
        parser.add_argument(
            '--fail-on-unexpected', action='store_true',
            help='Exit with code 2 (after the normal output) when a topic '
                 'changed that the model did not predict')
        add_format_argument(parser)

    def main(self, *, context):  # noqa: D102
        from colcon_rsia.render.check import render_check
        from colcon_rsia.system.bags import BagError
        from colcon_rsia.system.bags import measure_bag
        from colcon_rsia.system.check import check_one
        from colcon_rsia.system.check import check_two
        from colcon_rsia.system.check import DEFAULT_TOLERANCE
        args = context.args
        if len(args.bag) > 2:
            return '--bag: give one bag, or two (before and after a change)'
        tolerance = DEFAULT_TOLERANCE if args.tolerance is None \
            else args.tolerance
        if not 0 <= tolerance < 1:
            return f'--tolerance {tolerance}: expected a fraction in [0, 1)'
        two = len(args.bag) == 2
        if two and not (args.changed or args.since):
            return 'two bags need --changed or --since: the change ' \
                'between them'
        if not two and (args.changed or args.since):
            return '--changed/--since need two bags (before and after)'
        system, error = load_system_from_args(args, logger)
        if error:
            return error
        try:
            measured = [measure_bag(path, progress=_progress)
                        for path in args.bag]
        except BagError as e:
            return printable(e)
        if two:
            changed, _, error = select_changed(system, args)
            if error:
                return error
            result = check_two(system, *measured, changed,
                               tolerance=tolerance, model_name=args.model)
        else:
            result = check_one(system, measured[0], tolerance=tolerance)
        print(render_check(result, args.format), end='')
        if args.fail_on_unexpected and result['unexpected_changes']:
            sys.stdout.flush()
            print(printable(
                'rsia: topics changed that the model did not predict: ' +
                ', '.join(m['topic'] for m in result['unexpected_changes'])),
                file=sys.stderr)
            return UNEXPECTED_EXIT_CODE
        stale = stale_gate_message(system, '--fail-on-unexpected') \
            if args.fail_on_unexpected else None
        if stale:
            sys.stdout.flush()
            print(stale, file=sys.stderr)
            return UNEXPECTED_EXIT_CODE
        return 0


def _progress(line):
    print(printable(f'rsia: {line}'), file=sys.stderr)
