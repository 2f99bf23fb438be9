# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import os

from colcon_core.logging import colcon_logger
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.safe_files import printable
from colcon_rsia.subverb import RsiaSubverbExtensionPoint
from colcon_rsia.subverb.arguments import add_model_argument
from colcon_rsia.subverb.arguments import add_since_argument
from colcon_rsia.subverb.arguments import add_system_arguments
from colcon_rsia.system.workspace import load_system_from_args
from colcon_rsia.system.workspace import select_changed

logger = colcon_logger.getChild(__name__)

# beside the packages' build directories; a hyphen, which no ROS package
# name has, keeps it apart from them, and no leading dot keeps it visible
# to CI artifact uploads that skip hidden files
DEFAULT_OUTPUT_DIRNAME = 'rsia-report'


class ReportRsiaSubverb(RsiaSubverbExtensionPoint):
    """Write a workspace report: HTML page, graph files, PR summary."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        add_system_arguments(parser)
        group = parser.add_mutually_exclusive_group()
        group.add_argument(
            '--changed', nargs='+', metavar='PKG/EXE',
            help='The changed nodes (package/executable, or package/plugin '
                 'for nodelets); without --changed or --since the report '
                 'shows no impact set')
        add_since_argument(group)
        add_model_argument(parser)
        parser.add_argument(
            '--output', metavar='DIR', default=None,
            help='The directory the report is written into (created when '
                 'missing): index.html, graph.dot, graph.svg (with '
                 'Graphviz), graph.json, impact.json, summary.md '
                 f'(default: {DEFAULT_OUTPUT_DIRNAME} in the build base)')

    def main(self, *, context):  # noqa: D102
        from colcon_rsia.report.writer import write_report
        args = context.args
        system, error = load_system_from_args(args, logger)
        if error:
            return error
        changed, reasons, error = select_changed(system, args)
        if error:
            return error
        output = args.output or os.path.join(
            args.build_base, DEFAULT_OUTPUT_DIRNAME)
        try:
            written, notes = write_report(
                system, output, changed=changed, reasons=reasons,
                since=args.since, model_name=args.model)
        except OSError as e:
            return f"cannot write the report into '{output}': " \
                f'{e.strerror or e}'
        for note in notes:
            print(printable(f'rsia: {note}'))
        print(printable(f'rsia: report written to {os.path.abspath(output)}: '
                        f"{', '.join(written)}"))
        return 0
