# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The ROS 2 (rclcpp) test workspace, analysed unbuilt in model mode."""

import json

from conftest import run_colcon
from conftest import WORKSPACES
from helpers import read_yaml
from projection import project_nodes
import pytest

EXPECTED = sorted((WORKSPACES / 'ros2' / 'expected').glob('*.yaml'))


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
    expected = read_yaml(path)
    summary = _summary(ros2_build_base, expected['package'])
    assert summary['header_mode'] == 'model'
    assert project_nodes(summary['nodes'], named=True) == \
        project_nodes(expected.get('nodes') or [], named=True)


def test_expected_files_cover_every_analyzed_package(ros2_build_base):
    analyzed = {
        p.parent.parent.name
        for p in ros2_build_base.glob('*/rsia/summary.json')}
    assert analyzed == {read_yaml(p)['package'] for p in EXPECTED}


def test_errors_are_left_only_where_the_ast_has_every_call(ros2_build_base):
    # repairing pays only where the AST lost a call: a unit left with
    # parse errors is one whose every endpoint call has a fact of the AST
    for path in EXPECTED:
        summary = _summary(ros2_build_base, read_yaml(path)['package'])
        problems = [d for d in summary.get('diagnostics', [])
                    if 'parse error' not in d]
        assert problems == []
        coverage = summary['coverage']
        with_errors = {u['file'] for u in coverage['units']
                       if u['package_errors']}
        sites = [c for c in coverage['call_sites']
                 if c['file'] in with_errors]
        assert all(c['recorded'] != 'none' and c['origin'] == 'ast'
                   for c in sites), sites
        # (and the coverage says so: the errors left cost no call)
        assert [u['file'] for u in coverage['units'] if u['lost_calls']] \
            == []


def _graph(build_base, *launch):
    words = ['rsia', 'graph', '--base-paths', str(WORKSPACES / 'ros2' / 'src'),
             '--format', 'json']
    if launch:
        words += ['--launch', *launch]
    result = run_colcon(words, cwd=build_base.parent, check=True)
    return json.loads(result.stdout)


def _endpoints(graph):
    """{instance name: ({published topics}, {subscribed topics})}."""
    return {
        node['name']: ({p['resolved'] for p in node['publishers']},
                       {s['resolved'] for s in node['subscribers']})
        for node in graph['nodes']}


def test_names_without_a_launch_file_come_from_the_code(ros2_build_base):
    nodes = {n['id']: n for n in _graph(ros2_build_base)['nodes']}
    endpoints = _endpoints({'nodes': list(nodes.values())})
    # Node("odom_relay", "robot1"): every relative name under /robot1
    assert nodes['rsia_ros2_core/odom_relay']['name'] == '/robot1/odom_relay'
    assert '/robot1/odom_out' in endpoints['/robot1/odom_relay'][0]
    # create_sub_node("arm") of Node("arm_driver", "robot")
    assert endpoints['/robot/arm_driver'] == (
        {'/robot/arm/joint_states', '/robot/arm/gripper/position'},
        {'/robot/arm/command'})
    # topics from declare_parameter defaults, ~/status under the node name
    assert endpoints['/scan_filter'] == (
        {'/scan_filtered', '/scan_filter/status'}, {'/scan'})
    # named through its classes: the base's ~/status follows the name
    assert endpoints['/front_sonar'] == (
        {'/range', '/front_sonar/status', '/ping'}, {'/sonar_enable'})
    # one executable, two nodes, each under its own name
    assert nodes['rsia_ros2_core/multi_node/detector']['name'] == '/detector'
    assert '/detector/rate' in endpoints['/detector'][0]


@pytest.mark.parametrize('launch_file', ['robot.launch.py', 'robot.launch.xml'])
def test_ros2_launch_parameters_names_and_multi_node_executables(
        ros2_build_base, launch_file):
    graph = _graph(ros2_build_base, 'rsia_ros2_core', launch_file)
    endpoints = _endpoints(graph)
    # multi_node runs two nodes; arm_driver keeps the namespace of its code
    assert set(endpoints) == {
        '/front/front_filter', '/camera', '/detector', '/robot/arm_driver'}
    # parameters decide the topics; ~/status follows the launch file's name
    assert endpoints['/front/front_filter'] == (
        {'/front/scan', '/front/front_filter/status'}, {'/lidar/front'})
    image = next(t for t in graph['topics'] if t['name'] == '/image')
    assert (image['publishers'], image['subscribers']) == (
        ['/camera'], ['/detector'])


def test_a_node_of_a_multi_node_executable_is_changed_by_its_id(
        ros2_build_base):
    # with the launch file the instances are /camera and /detector; the
    # summary's node id still names the one the change is in
    result = run_colcon(
        ['rsia', 'impact', '--base-paths', str(WORKSPACES / 'ros2' / 'src'),
         '--launch', 'rsia_ros2_core', 'robot.launch.py',
         '--changed', 'rsia_ros2_core/multi_node/camera', '--format', 'json'],
        cwd=ros2_build_base.parent, check=True)
    impact = json.loads(result.stdout)
    assert impact['changed'] == ['/camera']
    # /image from the camera feeds the detector, nothing else
    assert impact['rate_impact'] == ['/detector']


def test_plugins_without_a_launch_file_are_in_their_hosts_namespace(
        ros2_build_base):
    endpoints = _endpoints(_graph(ros2_build_base))
    # a controller's name is its key in the controller manager's
    # parameters, which only a launch file gives: its private names
    # (~/odom, ~/command_echo, ~/cmd_vel) are not known
    assert endpoints['/OdometryController'] == ({None}, {None})
    # relative names are in the host's namespace, the root by default
    assert endpoints['/StraightLinePlanner'] == ({'/plan_preview'}, set())
    assert endpoints['/StateBroadcaster'] == ({'/joint_states'}, set())


def test_hosts_in_a_launch_file_load_the_plugins_their_parameters_name(
        ros2_build_base):
    graph = _graph(ros2_build_base, 'rsia_ros2_plugins', 'control.launch.py')
    endpoints = _endpoints(graph)
    # each controller is a node named after its key in controllers.yaml;
    # the planner runs in the planner server's node
    assert endpoints['/odometry_controller'] == (
        {'/odometry_controller/odom', '/odometry_controller/command_echo'},
        {'/odometry_controller/cmd_vel'})
    assert endpoints['/state_broadcaster'] == ({'/joint_states'}, set())
    # a controller type no analysed package has: an instance all the same
    outside = next(n for n in graph['nodes']
                   if n['id'] == '/joint_state_broadcaster')
    assert (outside['kind'], outside['publishers']) == ('unknown', [])
    planner = next(n for n in graph['nodes']
                   if n['id'] == '/planner_server/Straight')
    assert planner['name'] == '/planner_server'
    # the relay's remapped output is the controller's command input; two
    # more topics come from helpers compiled into rsia_ros2_common
    assert endpoints['/velocity_relay'][0] == {
        '/odometry_controller/cmd_vel', '/relay_status', '/debug/relayed',
        '/relay_mode', '/graph_announcements', '/relay_gauge'}


def test_a_host_periodic_edge_stops_the_rate_impact(ros2_build_base):
    result = run_colcon(
        ['rsia', 'impact', '--base-paths', str(WORKSPACES / 'ros2' / 'src'),
         '--launch', 'rsia_ros2_plugins', 'control.launch.py',
         '--changed', '/velocity_relay', '--format', 'json'],
        cwd=ros2_build_base.parent, check=True)
    impact = json.loads(result.stdout)
    # the relay's commands drive the odometry controller's command echo
    # (dependent), so its rate may follow; its odometry is paced by the
    # controller manager's loop, so the odometry relay reading it is out
    # of the rate impact, though data flows to it
    assert impact['rate_impact'] == ['/odometry_controller']
    assert impact['traditional_impact'] == [
        '/odometry_controller', '/robot1/odom_relay']


def test_a_launched_component_is_the_node_that_runs_its_class(
        ros2_build_base):
    graph = _graph(ros2_build_base, 'rsia_ros2_demo', 'composed.launch.py')
    nodes = {n['id']: n for n in graph['nodes']}
    # the lidar component is the lidar_node executable's node; the camera
    # one the component named after its generated executable
    assert set(nodes) == {'/robot/front_lidar', '/robot/camera'}
    assert _endpoints(graph) == {
        '/robot/front_lidar': ({'/robot/scan'}, set()),
        '/robot/camera': ({'/robot/image'}, set())}
