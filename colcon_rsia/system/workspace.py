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
from colcon_rsia.package.store import find_summaries
from colcon_rsia.package.store import read_summary
from colcon_rsia.package.store import SummaryError
from colcon_rsia.system.impact import expand_changed
from colcon_rsia.system.impact import UnknownNodeError


def load_workspace(args, logger):
    """Read the summaries of the selected packages.

    Packages that were not analysed are skipped; an unusable summary is
    reported in one line and skipped, never hiding the others.

    :returns: the summaries and {package name: source path} of the
      packages found under the base paths
    """
    try:
        decorators = get_packages(args)
    except RuntimeError as e:
        logger.warning(str(e))
        decorators = []
    package_paths = {
        d.descriptor.name: str(d.descriptor.path) for d in decorators}
    selected = {d.descriptor.name for d in decorators if d.selected}
    found = find_summaries(os.path.abspath(args.build_base))
    summaries = []
    for name, path in sorted(found.items()):
        # with no package found under the base paths, take every summary
        if decorators and name not in selected:
            continue
        try:
            summaries.append(read_summary(path))
        except SummaryError as e:
            logger.warning(str(e))
    return summaries, package_paths


def load_system_from_args(args, logger):
    """The system graph the arguments describe, or an error message."""
    from colcon_rsia.system.load import LaunchArgumentError
    from colcon_rsia.system.load import load_system
    launch = getattr(args, 'launch', None)
    expected_errors = (LaunchArgumentError,)
    if launch:
        from colcon_rsia.launch import LaunchError
        expected_errors += (LaunchError,)
    summaries, package_paths = load_workspace(args, logger)
    try:
        system = load_system(
            summaries, launch=launch, package_paths=package_paths)
    except expected_errors as e:
        return None, str(e)
    for note in system.notes:
        print(f'note: {note}', file=sys.stderr)
    return system, None


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
            return None, {}, str(e)
        if not reasons:
            print(f'rsia: no analysed node changed since {args.since}',
                  file=sys.stderr)
        for line in describe_reasons(system, reasons):
            print(f'rsia: changed {line}', file=sys.stderr)
        return sorted(reasons), reasons, None
    if getattr(args, 'changed', None):
        reasons = {}
        for name in args.changed:
            try:
                ids = expand_changed(system, [name])
            except UnknownNodeError as e:
                return None, {}, str(e)
            for instance_id in ids:
                reasons.setdefault(instance_id, []).append(
                    'named with --changed' if name == instance_id else
                    f'named with --changed {name}')
        return sorted(reasons), reasons, None
    return None, {}, None
