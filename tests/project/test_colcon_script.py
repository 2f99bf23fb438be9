# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Every verb through the `colcon` script, with the colcon users install.

The tests' venv has colcon-common-extensions (what the ROS documentation
installs), so each command here meets colcon-argcomplete's and
colcon-defaults' parser decorators, as users' commands do. Each runs from
the workspace root with colcon's default base path.
"""

from importlib import metadata
import json
import os
import re

from conftest import run_colcon
from helpers import assert_no_traceback
from helpers import write_bag
import pytest

LASER = 'sysbot_drivers/laser_driver'
# the nodes the laser's rate reaches (test_workspaces/system/expected.yaml)
LASER_RATE_IMPACT = ['sysbot_navigation/planner',
                     'sysbot_perception/scan_filter']


def _subverbs():
    return sorted(e.name for e in metadata.entry_points(
        group='colcon_rsia.subverb'))


def _rsia(workspace, *args, env=None):
    result = run_colcon(['rsia', *args], cwd=workspace.root, env=env)
    assert_no_traceback(result)
    return result


def test_the_extensions_users_install_are_installed():
    # what the ROS documentation installs; the rest of this file is
    # meaningless without it
    metadata.distribution('colcon-common-extensions')


@pytest.mark.parametrize('subverb', [None] + _subverbs())
def test_help_of_every_verb(tmp_path, subverb):
    args = ['rsia'] + ([subverb] if subverb else []) + ['--help']
    result = run_colcon(args, cwd=tmp_path)
    assert_no_traceback(result)
    assert result.returncode == 0, result.stderr
    assert 'usage: ' in result.stdout


def test_impact(system_workspace):
    result = _rsia(system_workspace, 'impact', '--changed', LASER,
                   '--format', 'json')
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)['rate_impact'] == LASER_RATE_IMPACT


def test_usage_errors_exit_1(system_workspace):
    # (after --changed it would be a node name: colcon takes an unknown
    # option as a value there)
    unknown = _rsia(system_workspace, 'impact', '--no-such-option',
                    '--changed', LASER)
    assert unknown.returncode == 1
    assert 'unrecognized arguments: --no-such-option' in unknown.stderr
    nothing_changed = _rsia(system_workspace, 'impact')
    assert nothing_changed.returncode == 1
    assert '--changed --since --all is required' in nothing_changed.stderr
    no_subverb = _rsia(system_workspace)
    assert no_subverb.returncode == 1


def test_graph(system_workspace):
    result = _rsia(system_workspace, 'graph')
    assert result.returncode == 0, result.stderr
    # sysbot_navigation/planner subscribes /odom in src/planner.cpp:20
    assert '  subscribes /odom -> Planner::odomCallback src/planner.cpp:20' \
        in result.stdout.splitlines()
    assert not re.search(r'\bNone\b', result.stdout)


def test_rates(system_workspace):
    result = _rsia(system_workspace, 'rates', '--format', 'json')
    assert result.returncode == 0, result.stderr
    topics = {t['name']: t for t in json.loads(result.stdout)['topics']}
    # the planner's 5 Hz timer
    assert topics['/plan']['hz'] == 5.0


def test_coverage(system_workspace):
    result = _rsia(system_workspace, 'coverage', '--format', 'json')
    assert result.returncode == 0, result.stderr
    packages = {p['package'] for p in json.loads(result.stdout)['packages']}
    assert packages == {'sysbot_drivers', 'sysbot_navigation',
                        'sysbot_perception'}


def test_check(system_workspace, tmp_path):
    bag = write_bag(tmp_path / 'run.bag', {'/plan': 5.0})
    result = _rsia(system_workspace, 'check', '--bag', str(bag),
                   '--format', 'json')
    assert result.returncode == 0, result.stderr
    topics = {t['name']: t for t in json.loads(result.stdout)['topics']}
    assert topics['/plan']['status'] == 'ok'


def test_report_has_a_default_place(system_workspace):
    result = _rsia(system_workspace, 'report', '--changed', LASER)
    assert result.returncode == 0, result.stderr
    where = system_workspace.root / 'build' / 'rsia-report'
    assert f'report written to {where}' in result.stdout
    assert (where / 'index.html').is_file()
    assert LASER in (where / 'summary.md').read_text()


def test_a_closed_pipe_is_no_error(system_workspace):
    import subprocess
    from conftest import colcon_executable
    env = dict(os.environ,
               COLCON_HOME=str(system_workspace.root / '.colcon_home'))
    # `colcon rsia graph --format dot | head -1`
    graph = subprocess.Popen(
        [colcon_executable(), 'rsia', 'graph', '--format', 'dot'],
        cwd=system_workspace.root, env=env, stdout=subprocess.PIPE,
        stderr=subprocess.PIPE)
    first = graph.stdout.readline()
    graph.stdout.close()
    assert graph.wait(timeout=60) == 0
    assert first.startswith(b'digraph')
    assert b'Traceback' not in graph.stderr.read()


BROKEN_PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>broken_pkg</name>
  <version>0.0.1</version>
  <description>A node whose second file does not compile.</description>
  <maintainer email="someone@example.com">someone</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <depend>rclcpp</depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""
BROKEN_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(broken_pkg)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
add_executable(talker src/talker.cpp src/broken.cpp)
ament_target_dependencies(talker rclcpp)
install(TARGETS talker DESTINATION lib/${PROJECT_NAME})
ament_package()
"""
TALKER = """#include <rclcpp/rclcpp.hpp>
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("talker");
  rclcpp::spin(node);
  return 0;
}
"""
# line 3: a return statement without its semicolon
BROKEN = """int helper()
{
  return 0
}
"""


@pytest.fixture(scope='module')
def broken_workspace(tmp_path_factory):
    """An unbuilt workspace with one syntax error, analysed by the script."""
    root = tmp_path_factory.mktemp('broken')
    package = root / 'src' / 'broken_pkg'
    (package / 'src').mkdir(parents=True)
    (package / 'package.xml').write_text(BROKEN_PACKAGE_XML)
    (package / 'CMakeLists.txt').write_text(BROKEN_CMAKE)
    (package / 'src' / 'talker.cpp').write_text(TALKER)
    (package / 'src' / 'broken.cpp').write_text(BROKEN)
    result = run_colcon(['rsia', 'analyze'], cwd=root)
    assert_no_traceback(result)
    return root, result


def test_analyze_unbuilt(broken_workspace):
    root, result = broken_workspace
    assert result.returncode == 0, result.stdout + result.stderr
    assert 'rsia: broken_pkg: 1 nodes' in result.stdout
    summary = json.loads(
        (root / 'build' / 'broken_pkg' / 'rsia' / 'summary.json').read_text())
    assert [n['id'] for n in summary['nodes']] == ['broken_pkg/talker']


def test_problems_lists_each_with_its_place(broken_workspace):
    root, _ = broken_workspace
    result = run_colcon(['rsia', 'problems', '--format', 'json'], cwd=root)
    assert_no_traceback(result)
    assert result.returncode == 0, result.stderr
    [package] = json.loads(result.stdout)['packages']
    assert package['package'] == 'broken_pkg'
    assert package['status'] == 'analysed'
    errors = [p for p in package['problems']
              if p['reason'].startswith('parse error')]
    assert [(p['file'], p['line'], p['unit']) for p in errors] == \
        [('src/broken.cpp', 3, 'src/broken.cpp')]
    assert "expected ';'" in errors[0]['reason']
    text = run_colcon(['rsia', 'problems'], cwd=root).stdout
    assert 'broken_pkg: ' in text
    assert "  src/broken.cpp:3: parse error: expected ';'" in text


def test_options_from_colcon_defaults(system_workspace, tmp_path):
    # colcon-defaults names a verb's sub-verb `verb.subverb`
    defaults = tmp_path / 'defaults.yaml'
    defaults.write_text(
        'rsia.impact:\n  model: trigger\n  traditional: true\n'
        '  changed: [%s]\n' % LASER)
    env = {'COLCON_DEFAULTS_FILE': str(defaults)}
    result = _rsia(system_workspace, 'impact', env=env)
    assert result.returncode == 0, result.stderr
    assert f'changed: {LASER}' in result.stdout
    assert '(trigger model;' in result.stdout
    assert 'traditional impact:' in result.stdout
    # what the command line gives wins over the defaults
    result = _rsia(system_workspace, 'impact', '--model', 'paper', env=env)
    assert '(paper model;' in result.stdout


def _requirements(distribution):
    names = []
    for requirement in metadata.distribution(distribution).requires or []:
        name, _, marker = requirement.partition(';')
        if 'extra ==' not in marker:
            names.append(re.split(r'[\s<>=!~\[(]', name.strip())[0])
    return names


def _entry_points(distribution):
    return [f'{e.group}.{e.name}'
            for e in metadata.distribution(distribution).entry_points
            if e.group.startswith('colcon_')]


# what finds and identifies the packages of a ROS workspace
_BASE = {'colcon-ros'} | set(_requirements('colcon-ros'))
_ALONE = sorted(set(_requirements('colcon-common-extensions')) - _BASE -
                {'colcon-core'})


@pytest.mark.parametrize('extension', _ALONE)
def test_each_extension_alone(system_workspace, extension):
    blocked = [e for other in _ALONE if other != extension
               for e in _entry_points(other)]
    env = {'COLCON_EXTENSION_BLOCKLIST': os.pathsep.join(blocked)}
    for args in (['--help'], ['impact', '--help'],
                 ['impact', '--changed', LASER, '--format', 'json']):
        result = _rsia(system_workspace, *args, env=env)
        assert result.returncode == 0, (args, result.stderr)
    assert json.loads(result.stdout)['rate_impact'] == LASER_RATE_IMPACT
