# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Code that runs inside a host: nodelets, plugins, Gazebo plugins.

test_workspaces/hosted is analysed unbuilt (model mode). The expectations
are written from reading its sources: a nodelet's name, and so its private
names, comes only from what loads it; a plugin belongs to its host.
"""

import json

from colcon_rsia.summary import store
from colcon_rsia.summary.kinds import PATTERN_HOST_PERIODIC
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.package_summary import PackageSummary
from conftest import run_colcon
from conftest import WORKSPACES
import pytest

SRC = WORKSPACES / 'hosted' / 'src'


@pytest.fixture(scope='module')
def hosted(tmp_path_factory):
    """The build base of the hosted workspace, analysed once."""
    root = tmp_path_factory.mktemp('hosted')
    result = run_colcon(['rsia', 'analyze', '--base-paths', str(SRC)],
                        cwd=root, check=True)
    assert 'Traceback' not in result.stdout + result.stderr
    return root / 'build'


def _nodes(build_base, package):
    summary = store.read_summary(
        str(build_base / package / 'rsia' / 'summary.json'))
    return {node.id: node for node in summary.nodes}


def _graph(build_base, *launch):
    words = ['rsia', 'graph', '--base-paths', str(SRC), '--format', 'json']
    if launch:
        words += ['--launch', *launch]
    result = run_colcon(words, cwd=build_base.parent, check=True)
    return json.loads(result.stdout), result.stderr


def _names(graph):
    """{instance id: ({topic as written: resolved} published, subscribed)}."""
    return {
        node['id']: ({p['topic']: p['resolved'] for p in node['publishers']},
                     {s['topic']: s['resolved'] for s in node['subscribers']})
        for node in graph['nodes']}


def _labels(node):
    return {p.topic: (p.label, p.pattern) for p in node.publishers}


# --- one source, two targets ---------------------------------------------

def test_a_source_built_as_executable_and_nodelet_gives_distinct_ids(hosted):
    # counter.cpp is the `counter` executable and, with a define, the
    # nodelet the plugin XML names rsia_hosted_nodelets/counter: the reader
    # takes the summary (store.read_summary raises otherwise)
    nodes = _nodes(hosted, 'rsia_hosted_nodelets')
    assert nodes['rsia_hosted_nodelets/counter'].kind == 'nodelet'
    # the executable keeps its node name (ros::init "counter") in its id
    executable = nodes['rsia_hosted_nodelets/counter/counter']
    assert (executable.kind, executable.executable) == (
        'executable', 'counter')
    summary = store.read_summary(str(
        hosted / 'rsia_hosted_nodelets' / 'rsia' / 'summary.json'))
    assert any('rsia_hosted_nodelets/counter/counter' in d
               for d in summary.diagnostics)
    # the nodelet's class is behind the switch the unit was not parsed with
    assert any("nodelet 'rsia_hosted_nodelets/counter'" in d
               for d in summary.diagnostics)


def test_the_writer_never_writes_ids_its_reader_rejects(tmp_path):
    summary = PackageSummary(package='p', path='/p', tool_version='0')
    summary.nodes = [
        Node(id='p/a', package='p', executable='a', kind='executable',
             name='alpha'),
        Node(id='p/a', package='p', executable='a', kind='nodelet'),
        Node(id='p/a', package='p', executable='a', kind='plugin')]
    path = store.write_summary(str(tmp_path), summary)
    ids = sorted(n.id for n in store.read_summary(path).nodes)
    # the nodelet is launched by its plugin name: it keeps it
    assert ids == ['p/a', 'p/a/alpha', 'p/a/plugin']


# --- nodelets: their code, their names -------------------------------------

def test_a_nodelet_runs_the_classes_an_executable_also_compiles(hosted):
    # driver.cpp is built into driver_node and into the nodelet library
    driver = _nodes(hosted, 'rsia_hosted_nodelets')[
        'rsia_hosted_nodelets/DriverNodelet']
    assert _labels(driver) == {
        'packets': ('independent', 'no_subscribers'),
        'status': ('independent', 'no_subscribers')}


def test_a_nodelet_exported_through_a_typedef_runs_its_class_and_base(hosted):
    # XML type "Relay" is `typedef rsia_hosted_nodelets::Relay Relay`; the
    # base RelayBase holds a tf listener
    relay = _nodes(hosted, 'rsia_hosted_nodelets')['rsia/Relay']
    assert _labels(relay) == {'output': ('dependent', 'none')}
    assert sorted(s.topic for s in relay.subscribers) == [
        '/tf', '/tf_static', 'input']


def test_nodelet_private_names_without_a_launch_file_are_unknown(hosted):
    graph, stderr = _graph(hosted)
    names = _names(graph)
    # its name comes from what loads it: ~status and ~output are not
    # known; its public handle is in the (default) root namespace
    assert names['rsia_hosted_nodelets/DriverNodelet'][0] == {
        'packets': '/packets', 'status': None}
    assert names['rsia/Relay'][0] == {'output': None}
    assert names['rsia/Relay'][1]['input'] is None
    assert names['rsia/Relay'][1]['/tf'] == '/tf'
    assert 'rsia/Relay' in stderr
    # the executable built from the same source names itself
    assert names['rsia_hosted_nodelets/counter/counter'] == (
        {'count': '/counter/count'}, {'ticks': '/ticks'})


def test_a_launch_file_names_the_nodelets_it_loads(hosted):
    graph, _ = _graph(hosted, 'rsia_hosted_nodelets', 'driver.launch')
    assert _names(graph)['/robot/driver'][0] == {
        'packets': '/robot/packets', 'status': '/robot/driver/status'}


def test_a_nodelet_loaded_in_code_is_an_instance_named_there(hosted):
    # front_driver: loader.load("/front/driver", "rsia_hosted_nodelets/...")
    graph, _ = _graph(hosted)
    nodes = {n['id']: n for n in graph['nodes']}
    loaded = nodes['/front/driver']
    assert (loaded['kind'], loaded['name']) == ('nodelet', '/front/driver')
    assert _names(graph)['/front/driver'][0] == {
        'packets': '/front/packets', 'status': '/front/driver/status'}


# --- plugins whose host is not known ---------------------------------------

def test_plugins_of_unknown_hosts_have_no_names_but_global_ones(hosted):
    nodes = _nodes(hosted, 'rsia_hosted_plugins')
    assert {n.host for n in nodes.values()} == {None}
    graph, stderr = _graph(hosted)
    names = _names(graph)
    # a filter: the node that owns the filter chain gives its namespace
    assert names['rsia_hosted_plugins/SpikeFilter'][0] == {
        'spikes': None, 'dropped': None, '/spike_alarm': '/spike_alarm'}
    # an rviz display runs in rviz
    assert names['rsia_hosted_plugins/MarkerCount'][0] == {
        'marker_count': None}
    assert 'rsia_hosted_plugins/SpikeFilter' in stderr


# --- Gazebo plugins ---------------------------------------------------------

def test_ros1_gazebo_plugins_are_hosted_by_gzserver(hosted):
    nodes = _nodes(hosted, 'rsia_gazebo_plugins')
    odom = nodes['rsia_gazebo_plugins/OdomPlugin']
    assert (odom.kind, odom.plugin_class, odom.base_class, odom.host) == (
        'plugin', 'gazebo::OdomPlugin', 'gazebo::ModelPlugin', 'gzserver')
    # published only from the world-update handler, every simulation step;
    # the cmd_vel callback only stores the speed
    assert _labels(odom) == {
        'odom': ('independent', PATTERN_HOST_PERIODIC),
        '/tf': ('independent', PATTERN_HOST_PERIODIC)}
    assert [s.topic for s in odom.subscribers] == ['cmd_vel']
    tick = nodes['rsia_gazebo_plugins/TickPlugin']
    assert tick.base_class == 'gazebo::WorldPlugin'
    assert _labels(tick) == {'sim_tick': ('independent', 'no_subscribers')}


def test_ros1_gazebo_names_follow_the_node_handles_of_the_code(hosted):
    names = _names(_graph(hosted)[0])
    # NodeHandle(robot_namespace_): the SDF's robotNamespace
    assert names['rsia_gazebo_plugins/OdomPlugin'] == (
        {'odom': None, '/tf': '/tf'}, {'cmd_vel': None})
    # a default NodeHandle: gzserver's namespace, the root by default
    assert names['rsia_gazebo_plugins/TickPlugin'][0] == {
        'sim_tick': '/sim_tick'}


def test_ros2_gazebo_plugin_node_comes_from_gazebo_ros_node_get(hosted):
    plugin = _nodes(hosted, 'rsia_gazebo_ros2_plugins')[
        'rsia_gazebo_ros2_plugins/JointPublisher']
    assert (plugin.host, plugin.base_class) == (
        'gzserver', 'gazebo::ModelPlugin')
    assert _labels(plugin) == {
        'joint_states': ('independent', PATTERN_HOST_PERIODIC),
        '~/status': ('dependent', 'none')}
    # Node::Get(sdf): the SDF's <ros><namespace> (none: the root) and its
    # plugin name, which the code does not know
    names = _names(_graph(hosted)[0])
    assert names['rsia_gazebo_ros2_plugins/JointPublisher'] == (
        {'joint_states': '/joint_states', '~/status': None},
        {'target': '/target'})
