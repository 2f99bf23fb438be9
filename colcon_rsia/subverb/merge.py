# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import os
import sys

from colcon_core.argument_default import wrap_default_value
from colcon_core.argument_type import get_cwd_path_resolver
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.subverb import RsiaSubverbExtensionPoint

# a package was not merged (a conflict, a file that cannot be read)
MERGE_PROBLEM_EXIT_CODE = 1


class MergeRsiaSubverb(RsiaSubverbExtensionPoint):
    """Merge the analysis results of several build bases (CI shards) into one."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        parser.add_argument(
            '--from', dest='from_bases', nargs='+', required=True,
            metavar='BUILD_BASE', type=get_cwd_path_resolver(),
            help='The build bases to merge, each holding the analysis of '
                 'some packages (a shard of a CI matrix)')
        parser.add_argument(
            '--build-base',
            default=wrap_default_value('build'),
            type=get_cwd_path_resolver(),
            help='The build base merged into, which the queries then read '
                 '(default: build)')

    def main(self, *, context):  # noqa: D102
        from colcon_rsia.package.merge import merge_build_bases
        from colcon_rsia.package.merge import MergeUsageError
        from colcon_rsia.package.runner import build_base_problem
        from colcon_rsia.safe_files import display
        from colcon_rsia.safe_files import printable
        args = context.args
        target = os.path.abspath(args.build_base)
        problem = build_base_problem(target)
        if problem:
            return problem
        try:
            outcome = merge_build_bases(args.from_bases, target)
        except MergeUsageError as e:
            return printable(e)
        for note in outcome.notes:
            print(printable(f'rsia: note: {note}'), file=sys.stderr)
        for problem in outcome.problems:
            print(printable(f'rsia: merge: {problem}'), file=sys.stderr)
        duplicates = ''
        if outcome.duplicates:
            duplicates = (f' ({len(outcome.duplicates)} of them analysed the '
                          'same in several build bases)')
        count = len(outcome.merged)
        print(printable(
            f"rsia: merged {count} package{'s' if count != 1 else ''} into "
            f"'{display(target)}'{duplicates}"), flush=True)
        if outcome.problems:
            count = len(outcome.problems)
            print(printable(
                f"rsia: {count} merge problem{'s' if count != 1 else ''}: "
                'the packages they name were not merged'), file=sys.stderr)
            return MERGE_PROBLEM_EXIT_CODE
        return 0
