# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import argparse
import math
import os

from colcon_core.logging import colcon_logger
from colcon_core.package_selection import get_packages
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.subverb import RsiaSubverbExtensionPoint
from colcon_rsia.subverb.arguments import add_format_argument
from colcon_rsia.subverb.arguments import add_workspace_arguments

logger = colcon_logger.getChild(__name__)

# the exit code when --fail-under is not met (as --fail-on's)
CHECK_FAILED = 2


def percentage(text):
    """An argparse type: a number from 0 to 100."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not 0 <= value <= 100:  # nan too
        raise argparse.ArgumentTypeError(
            f"'{text}' is not a percentage from 0 to 100")
    return value


class CoverageRsiaSubverb(RsiaSubverbExtensionPoint):
    """Show what the analysis understood of each package, and what not."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        add_workspace_arguments(parser)
        add_format_argument(parser)
        parser.add_argument(
            '--missed', action='store_true',
            help='List every call site without a fact (text format)')
        parser.add_argument(
            '--repairs', action='store_true',
            help='List the repairs of the model mode, each with the rule '
                 'that made it, and their count by rule (text format)')
        parser.add_argument(
            '--fail-under', type=percentage, metavar='PERCENT', default=None,
            help='Exit with 2 when fewer than PERCENT %% of the publisher '
                 'and subscription call sites have a fact, or a package '
                 'failed (for CI)')

    def main(self, *, context):  # noqa: D102
        from colcon_rsia.package.coverage import FAILED
        from colcon_rsia.package.coverage import workspace_report
        from colcon_rsia.render.coverage import render_coverage
        from colcon_rsia.safe_files import max_file_mb_problem
        from colcon_rsia.summary import store
        args = context.args
        if max_file_mb_problem():
            return max_file_mb_problem()
        build_base = os.path.abspath(args.build_base)
        selected = [d.descriptor.name for d in get_packages(args)
                    if d.selected]
        summaries, failures, not_analysed = store.read_results(
            build_base, selected)
        report = workspace_report(summaries, failures, not_analysed)
        print(render_coverage(report, args.format, missed=args.missed,
                              repairs=args.repairs), end='')
        if args.fail_under is not None and (
                report['total']['percent'] < args.fail_under or
                any(p['status'] == FAILED for p in report['packages'])):
            return CHECK_FAILED
        return 0
