# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A workspace analysed in shards (a CI matrix), merged, queried as one.

Everything runs through the `colcon` script from the workspace root, the
packages unbuilt. test_workspaces/system: the drivers' topics cross into
perception and navigation (expected.yaml); its packages depend on none of
each other. test_workspaces/ros2: rsia_ros2_wrapped depends on
rsia_ros2_common and calls helpers compiled into its library, whose
summaries it reads from rsia_ros2_common's analysis (the relay's topics
are in test_workspaces/ros2/expected/rsia_ros2_wrapped.yaml). Last, the
build handler on two plain CMake packages, one depending on the other.
"""

import json
import shutil

from conftest import run_colcon
from conftest import WORKSPACES
import pytest

LASER = 'sysbot_drivers/laser_driver'


def _rsia(root, *args):
    result = run_colcon(['rsia', *args], cwd=root, timeout=600)
    assert 'Traceback' not in result.stderr, result.stderr
    assert result.returncode == 0, result.stdout + result.stderr
    return result


def _json(root, *args):
    return json.loads(_rsia(root, *args, '--format', 'json').stdout)


@pytest.fixture(scope='module')
def system_shards(tmp_path_factory):
    """The system workspace analysed whole, and in two shards merged."""
    root = tmp_path_factory.mktemp('shards')
    shutil.copytree(WORKSPACES / 'system' / 'src', root / 'src')
    _rsia(root, 'analyze', '--build-base', 'whole')
    # sysbot_perception in both shards
    _rsia(root, 'analyze', '--build-base', 'build_shard1',
          '--packages-select', 'sysbot_drivers', 'sysbot_perception')
    _rsia(root, 'analyze', '--build-base', 'build_shard2',
          '--packages-select', 'sysbot_perception', 'sysbot_navigation')
    merge = _rsia(root, 'merge', '--from', 'build_shard1', 'build_shard2')
    return root, merge


def test_shards_merged_give_the_answers_of_one_run(system_shards):
    root, merge = system_shards
    assert merge.stdout.strip() == (
        f"rsia: merged 3 packages into '{root / 'build'}' (1 of them "
        'analysed the same in several build bases)')
    assert merge.stderr == ''
    for query in (['impact', '--all'], ['graph'],
                  ['impact', '--changed', LASER, '--traditional']):
        assert _json(root, *query) == \
            _json(root, *query, '--build-base', 'whole'), query


def test_the_merged_base_crosses_the_shards(system_shards):
    root, _ = system_shards
    # the laser's /scan reaches the scan filter (perception), whose
    # /scan_filtered the planner (navigation) reads: two shards apart
    impact = _json(root, 'impact', '--changed', LASER)
    assert impact['rate_impact'] == [
        'sysbot_navigation/planner', 'sysbot_perception/scan_filter']
    graph = _json(root, 'graph')
    assert {n['package'] for n in graph['nodes']} == {
        'sysbot_drivers', 'sysbot_navigation', 'sysbot_perception'}


@pytest.fixture(scope='module')
def wrapped_workspace(tmp_path_factory):
    """rsia_ros2_common and rsia_ros2_wrapped, unbuilt."""
    root = tmp_path_factory.mktemp('wrapped')
    for package in ('rsia_ros2_common', 'rsia_ros2_wrapped'):
        shutil.copytree(WORKSPACES / 'ros2' / 'src' / package,
                        root / 'src' / package)
    return root


def _relay(root, build_base):
    summary = json.loads((root / build_base / 'rsia_ros2_wrapped' / 'rsia' /
                          'summary.json').read_text())
    (node,) = summary['nodes']
    return (summary['diagnostics'],
            {p['topic'] for p in node['publishers']},
            {s['topic'] for s in node['subscribers']})


def _missing_common(diagnostics):
    return [d for d in diagnostics if d.startswith(
        'the dependency rsia_ros2_common has no analysis of its sources in '
        'this build base')]


def test_a_shard_without_its_dependency_says_so(wrapped_workspace):
    root = wrapped_workspace
    result = _rsia(root, 'analyze', '--build-base', 'alone',
                   '--packages-select', 'rsia_ros2_wrapped')
    assert 'rsia_ros2_wrapped: 1 nodes' in result.stdout
    assert '1 problem, first: the dependency rsia_ros2_common' in \
        result.stdout
    diagnostics, publishers, subscribers = _relay(root, 'alone')
    assert len(_missing_common(diagnostics)) == 1
    assert "'colcon rsia merge'" in _missing_common(diagnostics)[0]
    # the helpers' topics are what is missing; the header's wrapper stays
    assert 'relay_status' in publishers
    assert not {'graph_announcements', 'relay_gauge'} & publishers
    assert subscribers == {'cmd_vel_in'}


def test_a_dependency_merged_in_first_gives_the_full_facts(
        wrapped_workspace):
    root = wrapped_workspace
    # a shard of the dependency, merged into the next stage's build base
    _rsia(root, 'analyze', '--build-base', 'stage1',
          '--packages-select', 'rsia_ros2_common')
    _rsia(root, 'merge', '--from', 'stage1', '--build-base', 'stage2')
    _rsia(root, 'analyze', '--build-base', 'stage2',
          '--packages-select', 'rsia_ros2_wrapped')
    # the same as a shard analysing both (--packages-up-to)
    _rsia(root, 'analyze', '--build-base', 'up_to',
          '--packages-up-to', 'rsia_ros2_wrapped')
    for build_base in ('stage2', 'up_to'):
        diagnostics, publishers, subscribers = _relay(root, build_base)
        assert _missing_common(diagnostics) == []
        assert {'graph_announcements', 'relay_gauge',
                'relay_status'} <= publishers
        assert subscribers == {'cmd_vel_in', 'graph_updates'}
    assert _relay(root, 'stage2') == _relay(root, 'up_to')


LIBRARY_CMAKE = """cmake_minimum_required(VERSION 3.10)
project(liba CXX)
add_library(a a.cpp)
install(TARGETS a DESTINATION lib)
"""
APP_CMAKE = """cmake_minimum_required(VERSION 3.10)
project(appb CXX)
find_package(liba QUIET)
add_executable(b b.cpp)
install(TARGETS b DESTINATION bin)
"""


def test_the_build_handler_says_a_dependency_was_not_analyzed(tmp_path):
    # plain CMake packages: appb depends on liba (its find_package)
    (tmp_path / 'src' / 'liba').mkdir(parents=True)
    (tmp_path / 'src' / 'liba' / 'CMakeLists.txt').write_text(LIBRARY_CMAKE)
    (tmp_path / 'src' / 'liba' / 'a.cpp').write_text('int a() { return 1; }\n')
    (tmp_path / 'src' / 'appb').mkdir(parents=True)
    (tmp_path / 'src' / 'appb' / 'CMakeLists.txt').write_text(APP_CMAKE)
    (tmp_path / 'src' / 'appb' / 'b.cpp').write_text('int main() {}\n')
    handler = ['--event-handlers', 'rsia+',
               '--cmake-args', '-DCMAKE_EXPORT_COMPILE_COMMANDS=ON']

    def build(package, *args):
        run_colcon(['build', '--packages-select', package, *args],
                   cwd=tmp_path, check=True)
        return json.loads((tmp_path / 'build' / package / 'rsia' /
                           'summary.json').read_text())['diagnostics'] \
            if args else None

    build('liba')  # without the analysis
    assert build('appb', *handler) == [
        'the dependency liba has no analysis of its sources in this build '
        'base: calls into its libraries give no facts here. Analyse it in '
        'the same run (e.g. with --packages-up-to) or merge its results in '
        "first ('colcon rsia merge'), then analyse this package again"]
    build('liba', *handler)
    assert build('appb', *handler) == []
