# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The analysis of the ROS 1 test workspace against hand-written files."""

import json
import re
import shutil

from colcon_rsia.render.graph import graph_to_json
from colcon_rsia.summary.store import read_summary
from colcon_rsia.system.load import load_system
from conftest import run_colcon
from conftest import WORKSPACES
from helpers import read_yaml
from projection import check_evidence
from projection import project_nodes
import pytest

EXPECTED = sorted((WORKSPACES / 'ros1' / 'expected').glob('*.yaml'))
# the calls a publish site may name, by the API that publishes there
PUBLISH_WORDS = re.compile(
    r'publish|sendTransform|unlockAndPublish|update|broadcast')


@pytest.mark.parametrize('path', EXPECTED, ids=[p.stem for p in EXPECTED])
def test_package_matches_expected_file(ros1_workspace, path):
    expected = read_yaml(path)
    summary = ros1_workspace.summary(expected['package'])
    want = project_nodes(expected.get('nodes') or [])
    got = project_nodes(summary['nodes'])
    assert sorted(got) == sorted(want), 'node ids differ'
    for node_id in sorted(want):
        for section in ('publishers', 'subscribers', 'timers', 'services',
                        'actions', 'clients'):
            assert got[node_id][section] == want[node_id][section], \
                f'{node_id} {section}'
        assert got[node_id]['kind'] == want[node_id]['kind'], node_id


def test_expected_files_cover_every_analyzed_package(ros1_workspace):
    analyzed = {
        p.parent.parent.name
        for p in ros1_workspace.build_base.glob('*/rsia/summary.json')}
    assert analyzed == {read_yaml(p)['package'] for p in EXPECTED}


def test_every_label_has_evidence_pointing_at_code(ros1_workspace):
    checked = 0
    for path in EXPECTED:
        summary = ros1_workspace.summary(read_yaml(path)['package'])
        checked += check_evidence(summary, PUBLISH_WORDS)
    assert checked > 0


@pytest.fixture(scope='module')
def unbuilt_model_summaries(tmp_path_factory):
    """The ros1 workspace analysed without a build, with the model headers."""
    root = tmp_path_factory.mktemp('ros1_unbuilt')
    result = run_colcon(
        ['rsia', 'analyze', '--base-paths', str(WORKSPACES / 'ros1' / 'src'),
         '--header-mode', 'model'], cwd=root, check=True)
    assert 'Traceback' not in result.stdout + result.stderr
    return root / 'build'


def _assert_matches_expected_file(build_base, path, header_mode):
    expected = read_yaml(path)
    summary = json.loads((
        build_base / expected['package'] / 'rsia' /
        'summary.json').read_text())
    assert summary['header_mode'] == header_mode
    assert project_nodes(summary['nodes']) == \
        project_nodes(expected.get('nodes') or [])


@pytest.mark.parametrize('path', EXPECTED, ids=[p.stem for p in EXPECTED])
def test_unbuilt_workspace_in_model_mode_matches_expected_file(
        unbuilt_model_summaries, path):
    _assert_matches_expected_file(unbuilt_model_summaries, path, 'model')


@pytest.fixture(scope='module')
def built_exact_summaries(ros1_workspace, tmp_path_factory):
    """The built ros1 workspace analysed in exact mode, into another base.

    Its compile databases and CMake's codemodel are copied, so the units
    are parsed again, with the real headers (units of one target share
    them precompiled: frontend/cpp/shared_headers.py).
    """
    build = tmp_path_factory.mktemp('ros1_exact') / 'build'
    for package in ros1_workspace.build_base.iterdir():
        if (package / 'compile_commands.json').is_file():
            shutil.copytree(package / '.cmake', build / package.name / '.cmake')
            shutil.copy(package / 'compile_commands.json',
                        build / package.name)
    result = run_colcon(
        ['rsia', 'analyze', '--build-base', str(build), '--header-mode',
         'exact'], cwd=ros1_workspace.root, check=True)
    assert 'Traceback' not in result.stdout + result.stderr
    assert 'precompiled' not in result.stdout, result.stdout
    return build


@pytest.mark.slow
@pytest.mark.parametrize('path', EXPECTED, ids=[p.stem for p in EXPECTED])
def test_built_workspace_in_exact_mode_matches_expected_file(
        built_exact_summaries, path):
    _assert_matches_expected_file(built_exact_summaries, path, 'exact')
    # the precompiled headers are gone with the analysis
    assert not list(built_exact_summaries.glob('*/rsia/shared-headers'))


def test_node_names_come_from_ros_init(ros1_workspace):
    # written from the ros::init(argc, argv, "...") of each main; a nodelet
    # is named by the launch file that loads it, never by its code
    expected = {
        'rsia_clocks/qt_ticker': 'qt_ticker',
        'rsia_clocks/asio_beacon': 'asio_beacon',
        'rsia_clocks/steady_loop': 'steady_loop',
        'rsia_control/joint_controller': 'joint_controller',
        'rsia_control/cmd_mux': 'cmd_mux',
        'rsia_control/trajectory_server': 'trajectory_server',
        'rsia_control/mission_client': 'mission_client',
        'rsia_control/heartbeat_relay': 'heartbeat_relay',
        'rsia_drivers/laser_driver': 'laser_driver',
        'rsia_drivers/camera_driver': 'camera_driver',
        'rsia_drivers/base_controller': 'base_controller',
        'rsia_localization/odom_tf_broadcaster': 'odom_tf_broadcaster',
        'rsia_localization/tf_monitor': 'tf_monitor',
        'rsia_localization/pose_options_relay': 'pose_options_relay',
        'rsia_localization/named_handles': 'named_handles',
        'rsia_localization/ekf_node': 'ekf_se',
        'rsia_localization/ukf_node': 'ukf_se',
        'rsia_nodelets/ScanThrottle': None,
        'rsia_perception/scan_relay': 'scan_relay',
        'rsia_perception/image_processor': 'image_processor',
        'rsia_perception/stereo_sync': 'stereo_sync',
        'rsia_perception/lazy_relay': 'lazy_relay',
    }
    names = {}
    for path in EXPECTED:
        summary = ros1_workspace.summary(read_yaml(path)['package'])
        names.update({n['id']: n['name'] for n in summary['nodes']})
    assert names == expected


def test_namespaces_from_values_resolve_or_stay_unknown(ros1_workspace):
    # written from src/rsia_localization/src/named_handles.cpp
    summary = ros1_workspace.summary('rsia_localization')
    system = graph_to_json(load_system([read_summary(str(
        ros1_workspace.build_base / 'rsia_localization' / 'rsia' /
        'summary.json'))]))
    [node] = [n for n in system['nodes']
              if n['id'] == 'rsia_localization/named_handles']
    resolved = {p['topic']: p['resolved'] for p in node['publishers']}
    resolved.update({s['topic']: s['resolved'] for s in node['subscribers']})
    # a string variable set once is its literal; a constructor argument
    # from the command line is not known: not a name in the root namespace
    assert resolved == {'pose': '/turtle1/pose', 'status': None, 'cmd': None}
    notes = [d for d in summary['diagnostics'] if 'named_handles.cpp' in d]
    assert len(notes) == 2 and all(
        'note:' in n and "'name'" in n for n in notes), notes


def test_a_class_template_node_takes_the_handles_its_main_passes(
        ros1_workspace):
    # written from src/rsia_localization/src/{filter_node,ekf_node}.cpp:
    # FilterNode<Ekf>(nh, nh_priv) keeps the root handle and the private
    # one in members; the calls of main reach the template's members
    system = graph_to_json(load_system([read_summary(str(
        ros1_workspace.build_base / 'rsia_localization' / 'rsia' /
        'summary.json'))]))
    resolved = {}
    for node in system['nodes']:
        if node['id'] in ('rsia_localization/ekf_node',
                          'rsia_localization/ukf_node'):
            resolved[node['id']] = sorted(
                e['resolved'] for e in node['publishers'] +
                node['subscribers'])
    assert resolved == {
        'rsia_localization/ekf_node': [
            '/ekf_se/set_pose', '/pose/filtered', '/twist'],
        'rsia_localization/ukf_node': [
            '/pose/filtered', '/twist', '/ukf_se/set_pose'],
    }
