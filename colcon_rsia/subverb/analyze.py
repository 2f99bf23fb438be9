# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

import argparse
import os
import sys
import time

from colcon_core.logging import colcon_logger
from colcon_core.package_selection import get_packages
from colcon_core.plugin_system import satisfies_version
from colcon_rsia.environment_variables import \
    HEADER_MODE_ENVIRONMENT_VARIABLE
from colcon_rsia.subverb import RsiaSubverbExtensionPoint
from colcon_rsia.subverb.arguments import add_workspace_arguments

logger = colcon_logger.getChild(__name__)

# a package failed: `colcon rsia analyze && colcon rsia impact ...` stops
# (the build handler never fails a build)
ANALYSIS_FAILED_EXIT_CODE = 1


def positive_int(text):
    """An argparse type: a whole number of at least 1."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(
            f"'{text}' is not a whole number of 1 or more")
    return value


class AnalyzeRsiaSubverb(RsiaSubverbExtensionPoint):
    """(Re)analyse the selected packages from their compile databases."""

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            RsiaSubverbExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')

    def add_arguments(self, *, parser):  # noqa: D102
        add_workspace_arguments(parser)
        parser.add_argument(
            '--header-mode', choices=('model', 'exact'), default=None,
            help='model: parse with the model headers of the ROS API and '
                 'stand-ins for the rest (fast, needs no ROS installation); '
                 'exact: with the headers the compiler used. Default: the '
                 f'{HEADER_MODE_ENVIRONMENT_VARIABLE.name} environment '
                 'variable, else model')
        parser.add_argument(
            '--repair', choices=('when-it-pays', 'always'),
            default='when-it-pays',
            help='model mode: repair a unit when its AST lost calls the '
                 'tokens show, or once when what its package learnt from '
                 'the other units answers its errors (when-it-pays), or '
                 'whenever its own code has parse errors (always: fewer '
                 'errors, more parses) (default: when-it-pays)')
        parser.add_argument(
            '--jobs', type=positive_int, default=None, metavar='N',
            help='Translation units parsed in parallel, each in a worker '
                 'process (default: the number of CPUs)')

    def main(self, *, context):  # noqa: D102
        # imported here: every colcon call loads this module, only
        # `colcon rsia analyze` needs the analysis
        from colcon_rsia.package.coverage import workspace_report
        from colcon_rsia.package import shared_cache
        from colcon_rsia.package import workers
        from colcon_rsia.package.environment import environment_problems
        from colcon_rsia.package.runner import analyze
        from colcon_rsia.package.runner import build_base_problem
        from colcon_rsia.render.coverage import total_line
        from colcon_rsia.safe_files import printable
        args = context.args
        problems = environment_problems()
        if problems:
            return '\n'.join(printable(p) for p in problems)
        problem = build_base_problem(os.path.abspath(args.build_base))
        if problem:
            return problem
        packages = get_packages(args)
        decorators = [d for d in packages if d.selected]
        package_dirs = sorted({
            os.path.abspath(str(d.descriptor.path)) for d in packages})
        by_name = {d.descriptor.name: d.descriptor for d in packages}
        build_base = os.path.abspath(args.build_base)
        started = time.monotonic()
        analysed = 0
        summaries = []
        failures = {}
        try:
            for number, decorator in enumerate(decorators, start=1):
                pkg = decorator.descriptor
                print(printable(
                    f'[{number}/{len(decorators)}] analysing {pkg.name} ...'),
                    flush=True)
                outcome = analyze(
                    name=pkg.name, package_type=pkg.type,
                    path=str(pkg.path),
                    build_base=os.path.join(build_base, pkg.name),
                    jobs=args.jobs, header_mode=args.header_mode,
                    repair=args.repair,
                    workspace_package_dirs=package_dirs, without_build=True,
                    dependencies=[
                        (n, by_name[n].type,
                         os.path.abspath(str(by_name[n].path)))
                        for n in decorator.recursive_dependencies or ()
                        if n in by_name])
                print(outcome.line(), flush=True)
                analysed += outcome.summary is not None
                if outcome.summary is not None:
                    summaries.append(outcome.summary)
                elif outcome.error is not None:
                    failures[pkg.name] = outcome.error
        finally:
            # the worker processes parsed every package's units: they end
            # with the command
            workers.shutdown()
        print(f'rsia: analysed {analysed} of {len(decorators)} packages in '
              f'{time.monotonic() - started:.1f}s', flush=True)
        if shared_cache.statistics_line():
            print(shared_cache.statistics_line(), flush=True)
        if summaries or not failures:
            print(total_line(workspace_report(summaries, failures)),
                  flush=True)
        else:
            print(f'rsia: no package was analysed ({len(failures)} failed)',
                  flush=True)
        if failures:
            print(printable(
                f'rsia: {len(failures)} of {len(decorators)} packages '
                f"failed: {', '.join(sorted(failures))}"), file=sys.stderr)
            return ANALYSIS_FAILED_EXIT_CODE
        return 0
