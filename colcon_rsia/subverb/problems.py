# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import os

from colcon_core.package_selection import get_packages
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.subverb import RsiaSubverbExtensionPoint
from colcon_rsia.subverb.arguments import add_format_argument
from colcon_rsia.subverb.arguments import add_workspace_arguments


class ProblemsRsiaSubverb(RsiaSubverbExtensionPoint):
    """List every problem the analysis met, with its file:line and reason."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        add_workspace_arguments(parser)
        add_format_argument(parser)

    def main(self, *, context):  # noqa: D102
        from colcon_rsia.package.problems import problems_report
        from colcon_rsia.package.problems import problems_to_text
        from colcon_rsia.render import JSON
        from colcon_rsia.render import json_text
        from colcon_rsia.safe_files import display
        from colcon_rsia.summary import store
        args = context.args
        selected = [d.descriptor.name for d in get_packages(args)
                    if d.selected]
        report = problems_report(*store.read_results(
            os.path.abspath(args.build_base), selected))
        # the text form of a problem is the build's too (the first problem
        # in the line of each package): it stays beside split_problem
        if args.format == JSON:
            print(json_text(report), end='')
        else:
            print(display(problems_to_text(report)), end='')
        return 0
