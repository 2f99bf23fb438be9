# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The ROS 2 (rclcpp) test workspace, analysed unbuilt in model mode."""

import json

from conftest import run_colcon
from conftest import WORKSPACES
from projection import project_nodes
import pytest
import yaml

EXPECTED = sorted((WORKSPACES / 'ros2' / 'expected').glob('*.yaml'))


def _expected(path):
    with open(path) as h:
        return yaml.safe_load(h)


@pytest.fixture(scope='module')
def ros2_build_base(tmp_path_factory):
    """The ros2 workspace analysed once, unbuilt, with the model headers."""
    root = tmp_path_factory.mktemp('ros2_unbuilt')
    result = run_colcon(
        ['rsia', 'analyze', '--base-paths', str(WORKSPACES / 'ros2' / 'src')],
        cwd=root, check=True)
    assert 'Traceback' not in result.stdout + result.stderr
    return root / 'build'


def _summary(build_base, package):
    return json.loads(
        (build_base / package / 'rsia' / 'summary.json').read_text())


@pytest.mark.parametrize('path', EXPECTED, ids=[p.stem for p in EXPECTED])
def test_package_matches_expected_file(ros2_build_base, path):
    expected = _expected(path)
    summary = _summary(ros2_build_base, expected['package'])
    assert summary['header_mode'] == 'model'
    assert project_nodes(summary['nodes'], named=True) == \
        project_nodes(expected.get('nodes') or [], named=True)


def test_expected_files_cover_every_analysed_package(ros2_build_base):
    analysed = {
        p.parent.parent.name
        for p in ros2_build_base.glob('*/rsia/summary.json')}
    assert analysed == {_expected(p)['package'] for p in EXPECTED}


def test_no_parse_errors_in_the_ros2_workspace(ros2_build_base):
    for path in EXPECTED:
        summary = _summary(ros2_build_base, _expected(path)['package'])
        assert not summary.get('diagnostics'), summary['diagnostics']
