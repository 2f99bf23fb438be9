# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Run the analysis of one package and say how it went, never raising.

Shared by the event handler and ``colcon rsia analyze`` so that both
analyse, report and fail the same way.
"""

import ast
from dataclasses import dataclass
import errno
import os
import re
import tempfile
import time
import traceback
from typing import Optional

from colcon_core.package_identification.ignore import IGNORE_MARKER
from colcon_rsia.environment_variables import HEADER_MODE_ENVIRONMENT_VARIABLE
from colcon_rsia.frontend.compile_db import COMPILE_DB_FILENAME
from colcon_rsia.package import build_paths
from colcon_rsia.package import coverage
from colcon_rsia.package.analysis import AnalysisError
from colcon_rsia.package.analysis import analyze_package
from colcon_rsia.package.analysis import REPAIR_WHEN_IT_PAYS
from colcon_rsia.package.dependencies import dependency_problems
from colcon_rsia.package.nodes import find_executables
from colcon_rsia.package.problems import problem_to_text
from colcon_rsia.package.problems import split_problem
from colcon_rsia.package.workers import check_stop
from colcon_rsia.package.workers import Interrupted
from colcon_rsia.safe_files import display
from colcon_rsia.safe_files import printable
from colcon_rsia.summary import store
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.package_summary import PackageSummary

EXPORT_FLAG = '-DCMAKE_EXPORT_COMPILE_COMMANDS=ON'

# the header mode unless asked otherwise: on the test workspaces the model
# headers give the same facts as the real ones at a fifth of the parse time
# (see docs/usage.md, Header modes); 'exact' remains for code whose ROS calls
# take types from libraries the model does not know
DEFAULT_HEADER_MODE = 'model'


@dataclass
class Outcome:
    """The result of analysing one package."""

    package: str
    summary: Optional[PackageSummary] = None
    warning: Optional[str] = None   # the package was not analysed, and why
    error: Optional[str] = None     # the analysis failed, and why
    # a package of a kind this version does not analyse (nothing to say
    # during a build)
    skipped: bool = False

    def line(self):
        """One line for the console (undecodable names escaped)."""
        if self.summary is not None:
            return printable(summary_line(self.summary))
        if self.warning is not None:
            return printable(f'rsia: {self.package}: {self.warning}')
        return printable(
            f'rsia: {self.package}: analysis failed: {self.error}')


def summary_line(summary):
    """``rsia: pkg: 2 nodes, 5 publishers (3 independent, 2 dependent)``."""
    publishers = [p for n in summary.nodes for p in n.publishers]
    independent = sum(1 for p in publishers if p.label == INDEPENDENT)
    line = (
        f'rsia: {summary.package}: {len(summary.nodes)} nodes, '
        f'{len(publishers)} publishers ({independent} independent, '
        f'{len(publishers) - independent} dependent) '
        f'in {summary.seconds:.1f}s')
    if summary.diagnostics:
        count = len(summary.diagnostics)
        first = problem_to_text(
            split_problem(summary.diagnostics[0], summary.path))
        line += f"; {count} problem{'s' if count != 1 else ''}, first: {first}"
        if count > 1:
            line += (" (all: 'colcon rsia problems --packages-select "
                     f"{summary.package}')")
    return line


def missing_compile_db_message(cmake_args):
    """Tell how to get a compile database, given the package's cmake args."""
    if cmake_args and any(
            a.startswith('-DCMAKE_EXPORT_COMPILE_COMMANDS') for a in cmake_args):
        return (
            f'no {COMPILE_DB_FILENAME} although the CMake arguments ask for '
            'it (the generator may not support it: use Makefiles or Ninja); '
            'not analysed')
    return (
        f'no {COMPILE_DB_FILENAME}; not analysed. Build with '
        f"'--cmake-args {EXPORT_FLAG}', or the 'compile-commands' mixin "
        "('--mixin compile-commands'), or add the flag to the 'build' "
        'cmake-args of your colcon defaults.yaml')


def exports_compile_commands(build_base):
    """Whether the package's CMake cache asks for compile_commands.json."""
    try:
        with open(os.path.join(build_base, 'CMakeCache.txt'),
                  encoding='utf-8', errors='replace') as h:
            text = h.read()
    except OSError:
        return False
    match = re.search(
        r'^CMAKE_EXPORT_COMPILE_COMMANDS(?::\w+)?=(\S*)', text, re.MULTILINE)
    return bool(match) and match.group(1).upper() in ('ON', 'TRUE', '1', 'YES')


def recorded_cmake_args(build_base):
    """The CMake arguments colcon-cmake recorded for the last configure."""
    try:
        with open(os.path.join(build_base, 'cmake_args.last')) as h:
            value = ast.literal_eval(h.read())
    except (OSError, ValueError, SyntaxError):
        return None
    return value if isinstance(value, list) else None


def default_header_mode():
    """The header mode when none is asked for (environment, else default)."""
    return os.environ.get(HEADER_MODE_ENVIRONMENT_VARIABLE.name) or \
        DEFAULT_HEADER_MODE


def workspace_packages(args):
    """``{name: (package type, source directory)}`` colcon discovers with `args`.

    Selected or not: a package may include another's headers. Their
    directories, not the base paths, are the workspace's sources: the
    default base path is the workspace root, which also holds the build
    base.
    """
    from colcon_core.package_discovery import discover_packages
    from colcon_core.package_identification import \
        get_package_identification_extensions
    descriptors = discover_packages(
        args, get_package_identification_extensions())
    return {d.name: (d.type, os.path.abspath(str(d.path)))
            for d in descriptors}


def analyze(*, name, package_type, path, build_base, cmake_args=None,
            jobs=None, header_mode=None, workspace_package_dirs=(),
            without_build=False, repair=REPAIR_WHEN_IT_PAYS,
            dependencies=()):
    """Analyse one package; return an :class:`Outcome`, never raise.

    :param header_mode: 'model' or 'exact'; None: :func:`default_header_mode`
    :param repair: when the model mode repairs a unit (see analyze_package)
    :param workspace_package_dirs: the source directories of all the
      workspace's packages (see :func:`workspace_packages`)
    :param bool without_build: analyse a package that has no compile
      database from its sources (else: warn how to get the database)
    :param dependencies: ``(name, package type, source directory)`` of the
      workspace's packages this one depends on (recursively): a C++
      package's analysis reads their wrappers, and says which have no
      analysis in the build base (:func:`cpp_dependencies`)
    """
    problem = build_paths.name_problem(name)
    if problem:
        return Outcome(display(name), warning=problem)
    try:
        return _analyze(
            name=name, package_type=package_type, path=path,
            build_base=build_base, cmake_args=cmake_args, jobs=jobs,
            header_mode=header_mode,
            workspace_package_dirs=workspace_package_dirs,
            without_build=without_build, repair=repair,
            dependencies=dependencies)
    except Interrupted:
        # nothing to say, nothing written: the build says it was interrupted
        return Outcome(display(name), skipped=True)
    except AnalysisError as e:
        outcome = Outcome(name, error=str(e))
    except OSError as e:
        # a full disk, a read-only build base: the user's situation
        outcome = Outcome(name, error=os_error_message(e))
    except Exception as e:  # noqa: B902
        # a bug of ours must never fail the user's build: say it and go on
        detail = traceback.format_exc().strip().splitlines()[-1]
        outcome = Outcome(name, error=f'internal error ({type(e).__name__}: '
                                      f'{detail}); please report it')
    try:
        # for `colcon rsia coverage`
        store.write_failure(build_base, name, outcome.error)
    except OSError:
        pass
    return outcome


# what a write meets on a disk that is full, read-only or not ours
_WRITE_ERRORS = frozenset({
    errno.EROFS, errno.ENOSPC, errno.EDQUOT, errno.EACCES, errno.EPERM,
    errno.ENOTDIR, errno.EEXIST, errno.EISDIR})


def os_error_message(error):
    """An OSError as what is wrong, naming the file."""
    where = f"'{display(error.filename)}'" if error.filename else 'a file'
    what = error.strerror or str(error)
    if error.errno in _WRITE_ERRORS:
        return f'cannot write {where}: {what}'
    return f'{what}: {where}'


def build_base_problem(build_base):
    """Why the build base cannot hold the summaries, or None.

    Makes it, marked as colcon build marks its own: the summaries, caches
    and stand-in headers are nothing the next command's package discovery
    should crawl (tens of thousands of directories in a large workspace).
    """
    if os.path.lexists(build_base) and not os.path.isdir(build_base):
        return f"--build-base '{display(build_base)}' is not a directory"
    try:
        os.makedirs(build_base, exist_ok=True)
        with tempfile.TemporaryFile(dir=build_base):
            pass
        marker = os.path.join(build_base, IGNORE_MARKER)
        if not os.path.lexists(marker):
            with open(marker, 'w'):
                pass
    except OSError as e:
        return (f"cannot write into --build-base '{display(build_base)}': "
                f'{e.strerror or e}')
    return None


def cpp_dependencies(dependencies):
    """``(name, path)`` of the dependencies that may offer wrappers.

    Only a C++ package's analysis writes wrappers (``wrappers.json``).

    :param dependencies: ``(name, package type, source directory)``
    """
    return [(name, path) for name, package_type, path in dependencies
            if PACKAGE_TYPE_ANALYSERS.get(package_type) in _CPP_ANALYSERS]


def _analyze(*, package_type, **request):
    """Analyse a package with the analyser of its type (or skip it)."""
    analyser = PACKAGE_TYPE_ANALYSERS.get(package_type)
    if analyser is None:
        return Outcome(
            request['name'],
            warning=f"package type '{package_type}' is not analysed "
                    'by this version; skipped', skipped=True)
    return analyser(**request)


# the analysers of the package types (below): each takes the arguments of
# `analyze` but the package type, and returns an Outcome


def _analyze_python(*, name, path, build_base, **_):
    """A package whose nodes are Python only."""
    # imported here: most colcon calls never analyse anything
    from colcon_rsia.package.python_analysis import analyze_python_package
    return Outcome(name, summary=analyze_python_package(
        name=name, path=path, build_base=build_base))


def _analyze_cpp_and_scripts(**request):
    """A package of C++ that may also install Python nodes (scripts)."""
    return _analyze_cpp(scripts=True, **request)


def _analyze_cpp(*, name, path, build_base, cmake_args, jobs, header_mode,
                 workspace_package_dirs, without_build, repair, dependencies,
                 scripts=False):
    """A package whose build produces a compile database.

    :param bool scripts: whether the package may also install Python
      nodes (scripts) besides its C++ ones
    """
    # imported here: most colcon calls never analyse anything
    from colcon_rsia.package.python_analysis import analyze_python_package
    from colcon_rsia.package.python_analysis import build_python_summary
    from colcon_rsia.package.python_nodes import find_python_nodes
    # the package's time includes CMake's configure of an unbuilt package
    started = time.monotonic()
    has_python = scripts and bool(find_python_nodes(path).nodes)
    has_database = os.path.isfile(
        os.path.join(build_base, COMPILE_DB_FILENAME))
    exported = exports_compile_commands(build_base)
    has_cpp = bool(find_executables(package_path=path, build_base=build_base))
    configured = time.monotonic() - started
    if not has_database and not exported and not without_build:
        if has_python and not has_cpp:
            # a package of Python scripts needs no compile database
            return Outcome(name, summary=analyze_python_package(
                name=name, path=path, build_base=build_base))
        if cmake_args is None:
            cmake_args = recorded_cmake_args(build_base)
        return Outcome(name, warning=missing_compile_db_message(cmake_args))
    if header_mode is None:
        header_mode = default_header_mode()
    wrapping = cpp_dependencies(dependencies)
    # CMake asked for a database but wrote none: nothing is compiled (a
    # header-only or launch-only package), so it has no C++ nodes
    summary = analyze_package(
        name=name, path=path, build_base=build_base, jobs=jobs,
        nothing_compiled=exported and not has_database,
        header_mode=header_mode, workspace_package_dirs=workspace_package_dirs,
        repair=repair, write=False,
        dependency_dirs=[d for _, d in wrapping])
    # the wrappers of dependencies analysed elsewhere were not read: say so
    # rather than give other facts than a run that analysed them first
    summary.diagnostics += dependency_problems(build_base, wrapping)
    summary.phases.configure = round(configured, 3)
    python_started = time.monotonic()
    if has_python:
        python = build_python_summary(name=name, path=path)
        summary.nodes = sorted(summary.nodes + python.nodes,
                               key=lambda n: n.id)
        summary.diagnostics += python.diagnostics
        summary.coverage.call_sites += python.coverage.call_sites
    elif scripts:
        # scripts nothing installs as a node (tools, tests, examples): their
        # call sites are in code no node runs, said as such, not as misses
        summary.coverage.call_sites += coverage.call_site_coverage(
            coverage.package_call_sites(path, python=True), nodes=[],
            units=[])
    summary.phases.python = round(time.monotonic() - python_started, 3)
    summary.seconds = round(time.monotonic() - started, 3)
    check_stop()
    store.write_summary(build_base, summary)
    return Outcome(name, summary=summary)


# package type (as colcon's package identification names it) -> its
# analyser; a package of a type missing here is skipped (Outcome.skipped)
PACKAGE_TYPE_ANALYSERS = {
    'cmake': _analyze_cpp,
    'ros.cmake': _analyze_cpp,
    'ros.catkin': _analyze_cpp_and_scripts,
    'ros.ament_cmake': _analyze_cpp_and_scripts,
    'ros.ament_python': _analyze_python,
}
# the analysers that write wrappers (``wrappers.json``)
_CPP_ANALYSERS = (_analyze_cpp, _analyze_cpp_and_scripts)
