# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The workspace the parsed command line selects: summaries, system, changes.

The query-time entry point of every subverb that reads the analysis: the
summaries of the selected packages (:func:`load_workspace`), the system
graph they and ``--launch`` describe (:func:`load_system_from_args`) and
the changed nodes ``--changed`` or ``--since`` name (:func:`select_changed`).
"""

import os
import sys

from colcon_core.package_selection import get_packages
from colcon_rsia.safe_files import printable
from colcon_rsia.summary.store import find_summaries
from colcon_rsia.summary.store import read_failure
from colcon_rsia.summary.store import read_summary
from colcon_rsia.summary.store import SummaryError
from colcon_rsia.system.impact import expand_changed
from colcon_rsia.system.impact import UnknownNodeError


def load_workspace(args, logger):
    """Read the summaries of the selected packages.

    Packages that were not analysed are skipped; an unusable summary is
    reported in one line and skipped, never hiding the others. A summary
    whose package's last analysis failed is used and reported as stale.

    :returns: the summaries, {package name: source path} of the packages
      found under the base paths and {package: why its last analysis
      failed} of the stale summaries
    """
    try:
        decorators = get_packages(args)
    except RuntimeError as e:
        logger.warning(printable(e))
        decorators = []
    package_paths = {
        d.descriptor.name: str(d.descriptor.path) for d in decorators}
    selected = {d.descriptor.name for d in decorators if d.selected}
    found = find_summaries(os.path.abspath(args.build_base))
    summaries = []
    stale = {}
    for name, path in sorted(found.items()):
        # with no package found under the base paths, take every summary
        if decorators and name not in selected:
            continue
        try:
            summaries.append(read_summary(path))
        except SummaryError as e:
            logger.warning(printable(e))
            continue
        # <build base>/<package>/rsia/summary.json
        failure = read_failure(os.path.dirname(os.path.dirname(path)))
        if failure is not None:
            stale[name] = failure
            logger.warning(printable(
                f'the summary of {name} is stale: its last analysis failed '
                f"({failure}); the analysis before it is used. Run 'colcon "
                "rsia analyze' again once the package is fixed"))
    return summaries, package_paths, stale


def load_system_from_args(args, logger):
    """The system graph the arguments describe, or an error message."""
    from colcon_rsia.safe_files import max_file_mb_problem
    from colcon_rsia.system.load import LaunchArgumentError
    # the one variable the queries read (summaries and launch files)
    if max_file_mb_problem():
        return None, max_file_mb_problem()
    from colcon_rsia.system.load import load_system
    launch = getattr(args, 'launch', None)
    expected_errors = (LaunchArgumentError,)
    if launch:
        from colcon_rsia.launch import LaunchError
        expected_errors += (LaunchError,)
    summaries, package_paths, stale = load_workspace(args, logger)
    try:
        system = load_system(
            summaries, launch=launch, package_paths=package_paths)
    except expected_errors as e:
        return None, printable(e)
    system.stale = stale
    for note in system.notes:
        print(printable(f'note: {note}'), file=sys.stderr)
    return system, None


def stale_gate_message(system, option):
    """Why a gate (``--fail-on``) fails on stale summaries, or None."""
    if not system.stale:
        return None
    names = sorted(system.stale)
    several = len(names) > 1
    return printable(
        f"rsia: {option}: the summar{'ies' if several else 'y'} of "
        f"{', '.join(names)} {'are' if several else 'is'} stale (the last "
        'analysis failed): the answer may be wrong')


def select_changed(system, args):
    """The changed instances ``--changed`` or ``--since`` names.

    Each changed instance and the reason it was chosen is printed on
    stderr for ``--since`` (stdout stays clean for JSON).

    :returns: (instance ids or None when neither option is given,
      {instance id: [reasons]}, an error message or None)
    """
    from colcon_rsia.system.since import changed_since
    from colcon_rsia.system.since import ChangeError
    from colcon_rsia.system.since import describe_reasons
    since = getattr(args, 'since', None)
    if since is not None and not since.strip():
        # an unset CI variable: `--since "$BASE"`
        return None, {}, ('--since needs a git revision, got an empty '
                          'string (is the variable that should hold it set?)')
    if since:
        try:
            reasons = changed_since(system, args.since)
        except ChangeError as e:
            return None, {}, printable(e)
        if not reasons:
            print(printable(f'rsia: no analysed node changed since '
                            f'{args.since}'), file=sys.stderr)
        for line in describe_reasons(system, reasons):
            print(printable(f'rsia: changed {line}'), file=sys.stderr)
        return sorted(reasons), reasons, None
    if getattr(args, 'changed', None):
        reasons = {}
        for name in args.changed:
            try:
                ids = expand_changed(system, [name])
            except UnknownNodeError as e:
                return None, {}, printable(e)
            for instance_id in ids:
                reasons.setdefault(instance_id, []).append(
                    'named with --changed' if name == instance_id else
                    f'named with --changed {name}')
        return sorted(reasons), reasons, None
    return None, {}, None
