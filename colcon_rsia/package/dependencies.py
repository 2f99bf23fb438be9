# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Whether the packages a package depends on were analysed in its build base.

A shard of a workspace (see ``colcon rsia merge``) that analyses a package
without its dependencies reads no wrappers of theirs: said, never silent.
"""

import os

from colcon_rsia.package.build_paths import name_problem
from colcon_rsia.summary.store import read_failure
from colcon_rsia.summary.store import read_summary
from colcon_rsia.summary.store import summary_path
from colcon_rsia.summary.store import SummaryError


def dependency_problems(package_build_base, dependencies):
    """Say which dependencies have no analysis of their sources here.

    A package's C++ analysis reads the wrappers of the packages it depends
    on from its siblings under the build base
    (``summary.wrapper_store.read_workspace_wrappers``); a dependency with no summary there,
    or one made from another source tree, offers none, and the calls into
    its libraries give no facts. (A summary without ``wrappers.json`` is a
    dependency with no wrappers: nothing is missing.)

    :param dependencies: ``(name, source directory)`` of the workspace's
      packages the package depends on, whose analysis may offer wrappers
    :returns: one diagnostic per dependency missing, by name
    """
    build_base = os.path.dirname(os.path.abspath(package_build_base))
    problems = []
    for name, path in sorted(dependencies):
        if name_problem(name):
            continue
        package_build = os.path.join(build_base, name)
        if _summary_source(summary_path(package_build)) == \
                os.path.abspath(path):
            continue
        failure = read_failure(package_build)
        if failure is not None:
            problems.append(
                f'the analysis of the dependency {name} failed ({failure}): '
                'calls into its libraries give no facts here')
        else:
            problems.append(
                f'the dependency {name} has no analysis of its sources in '
                'this build base: calls into its libraries give no facts '
                'here. Analyse it in the same run (e.g. with '
                "--packages-up-to) or merge its results in first ('colcon "
                "rsia merge'), then analyse this package again")
    return problems


# summary path -> ((modification time, size), its source directory): a
# package's dependencies are asked about for every package depending on them
_summary_sources = {}


def _summary_source(path):
    """The source directory a usable summary names, or None."""
    try:
        stat = os.stat(path)
    except OSError:
        return None
    key = (stat.st_mtime_ns, stat.st_size)
    known = _summary_sources.get(path)
    if known is not None and known[0] == key:
        return known[1]
    try:
        source = os.path.abspath(read_summary(path).path)
    except SummaryError:
        source = None
    _summary_sources[path] = (key, source)
    return source
