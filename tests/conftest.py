# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Session fixtures: each test workspace is compiled once per test run."""

from dataclasses import dataclass
import functools
import json
import os
from pathlib import Path
import re
import shutil
import subprocess
import sys

import pytest

REPO = Path(__file__).resolve().parents[1]
WORKSPACES = REPO / 'test_workspaces'
CMAKE_ARGS = [
    '-DCMAKE_EXPORT_COMPILE_COMMANDS=ON',
    # catkin needs Debian's python (its `catkin` module), not a venv's
    '-DPYTHON_EXECUTABLE=/usr/bin/python3',
]
# a whole workspace build must never take longer than this in CI
BUILD_TIMEOUT_S = 1500


# What makes a test slow: compiling a test workspace with colcon, a real
# browser, a real ROS system, running the colcon script end to end on
# generated workspaces, fuzzing. `pytest -m "not slow"` leaves these out
# (the quick run: the front ends, launch, system and report logic);
# `bash .ci/run` runs everything.
SLOW_FIXTURES = frozenset({
    'ros1_workspace', 'system_workspace', 'fig2_workspace', 'fig2_summaries',
    'triggers_workspace', 'fault_builds', 'python_workspace'})
# the suites whose every test runs colcon (or a sandboxed CMake, or worker
# processes) on workspaces of its own
SLOW_MODULES = frozenset({
    'test_ci_recipe', 'test_cmake_configure', 'test_cmake_sandbox',
    'test_colcon_script', 'test_cross_package_wrappers', 'test_faults',
    'test_hardening', 'test_hardening_round2', 'test_hosted',
    'test_launch_fuzz', 'test_merge', 'test_precompiled',
    'test_report_page', 'test_ros2_analysis', 'test_shards',
    'test_shared_cache', 'test_system', 'test_workers',
    'test_workspace_layouts'})


def pytest_collection_modifyitems(items):
    """Mark the tests that need a compiled workspace as slow."""
    for item in items:
        # by the file's name: the same in every subdirectory of tests/
        if SLOW_FIXTURES & set(getattr(item, 'fixturenames', ())) or \
                Path(item.path).stem in SLOW_MODULES:
            item.add_marker(pytest.mark.slow)


# The suite runs on every core (pytest-xdist, setup.cfg). A session or
# module fixture is made once per worker: each test file goes to one
# worker whole, and the files that use one built workspace go to the
# same worker (the first of these it names), so no workspace is compiled
# twice but where a file uses two.
BUILT_WORKSPACES = (
    'ros1_workspace', 'system_workspace', 'fig2_workspace',
    'triggers_workspace')


@pytest.hookimpl(tryfirst=True)
def pytest_xdist_make_scheduler(config, log):
    """Schedule whole files, those of one built workspace together."""
    from xdist.scheduler import LoadScopeScheduling

    class ByBuiltWorkspace(LoadScopeScheduling):

        def _split_scope(self, nodeid):
            test_file = nodeid.split('::', 1)[0]
            return _workspace_of(test_file) or test_file

    return ByBuiltWorkspace(config, log)


@functools.lru_cache(maxsize=None)
def _workspace_of(test_file):
    """The first built workspace a test file names, or None."""
    text = (REPO / test_file).read_text()
    return next((f'built:{name}' for name in BUILT_WORKSPACES
                 if re.search(rf'\b{name}\b', text)), None)


def colcon_executable():
    """The colcon of the interpreter running the tests."""
    candidate = Path(sys.executable).parent / 'colcon'
    if candidate.exists():
        return str(candidate)
    return shutil.which('colcon')


@dataclass
class Workspace:
    """A built test workspace."""

    root: Path
    src: Path
    returncode: int
    stdout: str
    stderr: str

    @property
    def build_base(self):  # noqa: D102
        return self.root / 'build'

    def summary(self, package):  # noqa: D102
        path = self.build_base / package / 'rsia' / 'summary.json'
        return json.loads(path.read_text())

    def colcon(self, *args, check=False):
        """Run colcon in the workspace root; return the completed process."""
        return run_colcon(list(args), cwd=self.root, check=check)


def analyze_source(root, package, text, *, file=None, repair='always',
                   cmake=None, build_base=None):
    """Analyze one C++ file as a package of its own, unbuilt (model mode).

    Repairs are made wherever the unit has errors (`repair`): the tests of
    what a repair declares need them whether or not the facts do.

    :param root: a scratch directory
    :param package: the package name (its directory under ``root``)
    :param text: the file's content, written to ``src/<package>.cpp``
      unless ``file`` names another path inside the package
    :param cmake: the package's CMakeLists.txt, if it has one
    :param build_base: where the analysis writes (``root/b`` by default)
    :returns: the package summary
    """
    from colcon_rsia.package import analysis
    path = Path(root) / package
    source = path / (file or f'src/{package}.cpp')
    source.parent.mkdir(parents=True, exist_ok=True)
    source.write_text(text)
    if cmake is not None:
        (path / 'CMakeLists.txt').write_text(cmake)
    return analysis.analyze_package(
        name=package, path=str(path),
        build_base=str(build_base or Path(root) / 'b'),
        jobs=1, header_mode='model', workspace_package_dirs=[str(path)],
        repair=repair)


def run_colcon(args, *, cwd, check=False, timeout=BUILD_TIMEOUT_S, env=None):
    """Run the `colcon` script in `cwd`; `env` adds environment variables."""
    env = dict(os.environ, **(env or {}))
    # no user mixins or defaults may change what the tests build
    env.setdefault('COLCON_HOME', str(Path(cwd) / '.colcon_home'))
    result = subprocess.run(
        [colcon_executable()] + args, cwd=str(cwd), env=env,
        capture_output=True, text=True, timeout=timeout)
    if check and result.returncode != 0:
        raise AssertionError(
            f'colcon {" ".join(args)} failed ({result.returncode}):\n'
            f'{result.stdout[-4000:]}\n{result.stderr[-4000:]}')
    return result


def build_workspace(src, root, *, handler=True, compile_commands=True,
                    extra=(), log_base=None, from_root=False):
    """colcon build a workspace whose sources are `src` into `root`.

    With `from_root`, the way users build: `src` is copied to
    ``root/src`` and colcon runs in `root` with its default base path.
    """
    root.mkdir(parents=True, exist_ok=True)
    args = ['--log-base', log_base] if log_base else []
    if from_root:
        shutil.copytree(src, root / 'src')
        src = root / 'src'
        args += ['build']
    else:
        args += ['build', '--base-paths', str(src)]
    if handler:
        args += ['--event-handlers', 'rsia+']
    cmake_args = list(CMAKE_ARGS) if compile_commands else CMAKE_ARGS[1:]
    args += list(extra) + ['--cmake-args'] + cmake_args
    result = run_colcon(args, cwd=root)
    return Workspace(root, Path(src), result.returncode, result.stdout,
                     result.stderr)


@pytest.fixture(scope='session')
def ros1_workspace(tmp_path_factory):
    """test_workspaces/ros1 built with the rsia event handler."""
    workspace = build_workspace(
        WORKSPACES / 'ros1' / 'src', tmp_path_factory.mktemp('ros1'),
        from_root=True)
    assert workspace.returncode == 0, workspace.stdout + workspace.stderr
    return workspace


@pytest.fixture(scope='session')
def system_workspace(tmp_path_factory):
    """test_workspaces/system built with the rsia event handler."""
    workspace = build_workspace(
        WORKSPACES / 'system' / 'src', tmp_path_factory.mktemp('system'),
        from_root=True)
    assert workspace.returncode == 0, workspace.stdout + workspace.stderr
    return workspace
