# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Launch front ends: ROS 1 XML, ROS 2 XML, YAML and Python, read statically."""

from pathlib import Path
import textwrap
import time

from colcon_rsia.launch import file_kind
from colcon_rsia.launch import LaunchError
from colcon_rsia.launch import LaunchResult
from colcon_rsia.launch import load_launch
from colcon_rsia.launch.common import MAX_INCLUDE_DEPTH
import pytest

FILES = Path(__file__).resolve().parent / 'launch_files'
ROS1_PKG = FILES / 'ros1_ws' / 'sysbot_bringup'
ROS2_PKG = FILES / 'ros2_ws' / 'robot_bringup'


def instances(result):
    """Instances by fully qualified name ('?' for unknown parts)."""
    out = {}
    for i in result.instances:
        ns = i.namespace if i.namespace is not None else '?'
        name = i.name if i.name is not None else '?'
        out[(ns.rstrip('/') + '/' + name)] = i
    return out


def write(directory, name, text):
    path = Path(directory) / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text).lstrip())
    return path


def load(path, **kwargs):
    kwargs.setdefault('environ', {})
    return load_launch(path, **kwargs)


def one_sentence(error):
    message = str(error)
    assert '\n' not in message
    assert message.endswith('.')
    return message


# ROS 1


def ros1_system(**arguments):
    return load(ROS1_PKG / 'launch' / 'system.launch', arguments=arguments,
                package_paths={'sysbot_bringup': ROS1_PKG})


def test_ros1_system():
    result = ros1_system()
    found = instances(result)
    assert sorted(found) == [
        '/monitor', '/sysbot/drivers/base/base_driver',
        '/sysbot/drivers/laser_driver', '/sysbot/obstacles',
        '/sysbot/perception_manager', '/sysbot/planner',
        '/sysbot/scan_filter']
    assert result.unresolved == []
    laser = found['/sysbot/drivers/laser_driver']
    assert (laser.package, laser.executable, laser.kind) == (
        'sysbot_drivers', 'laser_driver', 'node')
    # launch-level remap first, then the group's
    assert laser.remaps == [('/tf', '/sysbot/tf'), ('scan', 'base_scan')]
    # include args, an $(eval) arg with a fixed value, a default
    assert laser.params == {'port': '/dev/ttyUSB0', 'rate': 40,
                            'frame_id': 'laser'}
    assert laser.location.endswith('drivers.launch:6')
    base = found['/sysbot/drivers/base/base_driver']
    assert base.remaps[-1] == ('cmd_vel', '/cmd_vel')  # $(optenv) default
    planner = found['/sysbot/planner']
    assert planner.remaps == [('/tf', '/sysbot/tf'), ('scan', 'base_scan'),
                              ('map', '/map')]
    assert planner.params == {
        'robot_radius': 0.3,  # group-level <param name="planner/…">
        'frequency': 5.0, 'frame': 'sysbot/base_link',
        'planner_frequency': 2.0, 'costmap/width': 10,
        'costmap/inflation/radius': 0.55,
        'limits/max_vel': 0.5, 'limits/max_acc': 1.0}
    monitor = found['/monitor']
    assert monitor.remaps == [('/tf', '/sysbot/tf'), ('diagnostics', '/diag')]
    assert monitor.params == {'period': 2}
    assert [Path(f).name for f in result.files] == [
        'system.launch', 'drivers.launch', 'perception.launch',
        'planner.yaml']


def test_ros1_nodelets():
    found = instances(ros1_system())
    manager = found['/sysbot/perception_manager']
    assert (manager.package, manager.executable, manager.kind) == (
        'nodelet', 'nodelet', 'nodelet_manager')
    scan_filter = found['/sysbot/scan_filter']
    assert (scan_filter.package, scan_filter.executable, scan_filter.kind) \
        == ('sysbot_perception', 'sysbot_perception/ScanFilter', 'nodelet')
    assert scan_filter.remaps[-1] == ('scan_in', 'scan')
    assert scan_filter.params == {'window': 5}
    standalone = found['/sysbot/obstacles']
    assert standalone.kind == 'nodelet'
    assert standalone.executable == 'sysbot_perception/ObstacleDetector'


def test_ros1_command_line_overrides_defaults_not_values():
    result = ros1_system(robot='r7', use_nav='false', scan_rate='99',
                         sim='true')
    found = instances(result)
    assert '/r7/drivers/laser_driver' in found
    assert '/r7/planner' not in found      # group if="$(arg use_nav)"
    assert '/monitor' not in found         # unless="$(arg sim)"
    # scan_rate has a value= : the command line does not change it
    assert found['/r7/drivers/laser_driver'].params['rate'] == 40


def test_ros1_include_arguments_and_namespaces(tmp_path):
    write(tmp_path, 'inner.launch', """
        <launch>
          <arg name="who"/>
          <arg name="fixed" value="f"/>
          <node pkg="p" type="t" name="$(arg who)_node" ns="sub">
            <param name="fixed" value="$(arg fixed)"/>
          </node>
        </launch>""")
    top = write(tmp_path, 'top.launch', """
        <launch>
          <arg name="who" default="me"/>
          <include file="$(dirname)/inner.launch" ns="/abs">
            <arg name="who" value="$(arg who)"/>
            <arg name="fixed" value="other"/>
            <arg name="stray" value="1"/>
          </include>
          <include file="$(dirname)/missing.launch"/>
        </launch>""")
    result = load(top, arguments={'who': 'you'})
    node = instances(result)['/abs/sub/you_node']
    assert node.params == {'fixed': 'f'}
    notes = '\n'.join(result.unresolved)
    assert 'argument fixed has a fixed value' in notes
    assert 'argument stray is passed by the include but not declared' in notes
    assert 'missing.launch not found' in notes


def test_ros1_unknown_values_keep_the_instance(tmp_path):
    top = write(tmp_path, 'top.launch', """
        <launch>
          <arg name="required"/>
          <group ns="$(env ROBOT_NS)">
            <node pkg="p" type="a" name="a"/>
          </group>
          <node pkg="p" type="b" name="$(arg required)"/>
          <node pkg="p" type="c" name="c" if="$(optenv ENABLE_C)">
            <param name="cmd" command="cat /etc/hostname"/>
            <param name="rate" value="$(arg nope)"/>
          </node>
          <node pkg="p" type="d" name="$(anon d)"/>
        </launch>""")
    result = load(top)
    by_type = {i.executable: i for i in result.instances}
    assert by_type['a'].namespace is None
    assert 'ROBOT_NS' in by_type['a'].unresolved[0]
    assert by_type['b'].name is None
    assert 'required argument required is not given' in \
        by_type['b'].unresolved[0]
    c = by_type['c']
    assert c.params == {}
    assert any('only when if=' in n for n in c.unresolved)
    assert any('output of a command' in n for n in c.unresolved)
    assert any("argument 'nope' is not declared" in n for n in c.unresolved)
    d = by_type['d']
    assert d.name == 'd_anon'
    assert any('unique name chosen at run time' in n for n in d.unresolved)
    # the same file read twice gives the same placeholder
    assert load(top).instances[3].name == 'd_anon'
    # with the environment known, nothing is left open for 'a'
    result = load(top, environ={'ROBOT_NS': 'r', 'ENABLE_C': 'false'})
    found = instances(result)
    assert found['/r/a'].unresolved == []
    assert 'c' not in {i.executable for i in result.instances}


def test_ros1_eval_safe_subset(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    top = write(tmp_path, 'top.launch', """
        <launch>
          <arg name="a" default="3"/>
          <arg name="mode" default="fast"/>
          <arg name="rate" value="$(eval a * 2)"/>
          <arg name="bad" value="$(eval len(a))"/>
          <arg name="fast" value="$(eval arg('mode') == 'fast')"/>
          <arg name="label" value="$(eval mode + '_' + str(a))"/>
          <arg name="pick" value="$(eval 10 if mode == 'fast' else 1)"/>
          <arg name="evil"
               value="$(eval __import__('os').system('touch pwned'))"/>
          <node pkg="p" type="t" name="n" if="$(arg fast)">
            <param name="label" value="$(arg label)"/>
            <param name="pick" value="$(arg pick)"/>
            <param name="rate" value="$(arg rate)"/>
            <param name="evil" value="$(arg evil)"/>
          </node>
        </launch>""")
    result = load(top)
    node = result.instances[0]
    # arguments are numbers, booleans or text inside $(eval), as roslaunch
    # converts them
    assert node.params == {'label': 'fast_3', 'pick': 10, 'rate': 6}
    assert any('evil' in n for n in node.unresolved)
    assert any("unknown function 'len'" in n for n in result.unresolved)
    assert not (tmp_path / 'pwned').exists()


def test_ros1_self_and_mutually_referencing_args(tmp_path):
    top = write(tmp_path, 'top.launch', """
        <launch>
          <arg name="a" default="$(arg a)"/>
          <arg name="b" default="$(arg c)"/>
          <arg name="c" default="$(arg b)"/>
          <node pkg="p" type="t" name="$(arg a)" ns="$(arg c)"/>
        </launch>""")
    started = time.monotonic()
    result = load(top)
    assert time.monotonic() - started < 5
    node = result.instances[0]
    assert node.name is None and node.namespace is None
    notes = '\n'.join(result.unresolved)
    assert "argument 'a' refers to itself" in notes
    assert "argument 'c' is not declared" in notes


def test_ros1_rosparam_forms(tmp_path):
    write(tmp_path, 'params.yaml', """
        gains: {p: 1.0, i: 0.0}
        topics: [a, b]
        """)
    top = write(tmp_path, 'top.launch', """
        <launch>
          <arg name="rate" default="7"/>
          <rosparam file="$(dirname)/params.yaml" ns="ctrl"/>
          <group ns="robot">
            <rosparam param="ctrl/rate" subst_value="true">$(arg rate)</rosparam>
            <node pkg="p" type="t" name="ctrl">
              <rosparam param="list">[1, 2, 3]</rosparam>
              <rosparam command="delete" param="x"/>
              <param name="~private" value="true"/>
              <param name="yaml" type="yaml" value="{k: v}"/>
              <param name="/global" value="1"/>
            </node>
          </group>
          <node pkg="p" type="t" name="ctrl"/>
          <rosparam file="$(dirname)/nowhere.yaml"/>
          <rosparam file="$(find not_a_package)/x.yaml"/>
        </launch>""")
    result = load(top)
    found = instances(result)
    assert found['/robot/ctrl'].params == {
        'rate': 7, 'list': [1, 2, 3], 'private': True, 'yaml/k': 'v'}
    assert any('delete' in n for n in found['/robot/ctrl'].unresolved)
    assert found['/ctrl'].params == {'gains/p': 1.0, 'gains/i': 0.0,
                                     'topics': ['a', 'b']}
    notes = '\n'.join(result.unresolved)
    assert 'nowhere.yaml not found' in notes
    assert 'package not_a_package was not found' in notes


def test_ros1_installed_package_fallback(tmp_path, monkeypatch):
    share = tmp_path / 'opt' / 'share' / 'installed_pkg'
    write(share / 'launch', 'x.launch', """
        <launch><node pkg="installed_pkg" type="t" name="n"/></launch>""")
    monkeypatch.setattr(
        'colcon_rsia.launch.common.INSTALLED_SHARE_PATTERNS',
        (str(tmp_path / 'opt' / 'share' / '{}'),))
    top = write(tmp_path, 'top.launch', """
        <launch>
          <include file="$(find installed_pkg)/launch/x.launch"/>
        </launch>""")
    assert [i.name for i in load(top).instances] == ['n']


# ROS 2 XML


def test_ros2_xml_front_end(tmp_path):
    write(tmp_path, 'inner.launch.xml', """
        <launch>
          <arg name="rate" default="1"/>
          <node pkg="p" exec="inner" name="inner">
            <param name="rate" value="$(var rate)"/>
            <param name="top" value="$(var top_only)"/>
          </node>
        </launch>""")
    write(tmp_path, 'params.yaml', """
        /**:
          ros__parameters:
            everywhere: 1
        /team/a/worker:
          ros__parameters:
            only_a: true
        team:
          b:
            worker:
              ros__parameters:
                only_b: [1, 2]
        """)
    top = write(tmp_path, 'top.launch.xml', """
        <launch>
          <arg name="team" default="team"/>
          <arg name="top_only" default="t"/>
          <arg name="with_b" default="true"/>
          <set_remap from="/clock" to="/sim/clock"/>
          <group>
            <push-ros-namespace namespace="$(var team)"/>
            <group>
              <push_ros_namespace namespace="a"/>
              <set_remap from="cmd" to="cmd_a"/>
              <node pkg="p" exec="worker" name="worker">
                <param from="$(dirname)/params.yaml"/>
                <remap from="in" to="/shared/in"/>
              </node>
            </group>
            <group if="$(var with_b)">
              <push-ros-namespace namespace="b"/>
              <node pkg="p" exec="worker" name="worker"
                    args="--ros-args -r out:=out_b">
                <param from="$(dirname)/params.yaml"/>
                <param name="label" value="b"/>
              </node>
            </group>
            <node pkg="p" exec="boss" name="boss" namespace="/hq"/>
          </group>
          <let name="top_only" value="changed"/>
          <include file="$(dirname)/inner.launch.xml">
            <arg name="rate" value="$(eval 2 * 3)"/>
          </include>
          <node_container pkg="rclcpp_components" exec="component_container"
                          name="container" namespace="comp">
            <composable_node pkg="cam" plugin="cam::Driver" name="driver">
              <param name="fps" value="30"/>
              <remap from="image" to="image_raw"/>
            </composable_node>
          </node_container>
          <load_composable_node target="/comp/container">
            <composable_node pkg="cam" plugin="cam::Rectify" name="rect"
                             namespace="comp"/>
          </load_composable_node>
        </launch>""")
    result = load(top, arguments={'with_b': 'false'})
    assert file_kind(top, top.read_text()) == 'ros2'
    found = instances(result)
    # a component without a namespace gets the pushed one, not the
    # container's
    assert sorted(found) == ['/comp/container', '/comp/rect', '/driver',
                             '/hq/boss', '/inner', '/team/a/worker']
    worker = found['/team/a/worker']
    assert worker.remaps == [('/clock', '/sim/clock'), ('cmd', 'cmd_a'),
                             ('in', '/shared/in')]
    assert worker.params == {'everywhere': 1, 'only_a': True}
    # the group's set_remap and namespace do not leak out of it
    assert found['/hq/boss'].remaps == [('/clock', '/sim/clock')]
    assert found['/inner'].params == {'rate': 6, 'top': 'changed'}
    assert found['/comp/container'].kind == 'container'
    driver = found['/driver']
    assert (driver.kind, driver.package, driver.executable) == (
        'component', 'cam', 'cam::Driver')
    assert driver.params == {'fps': 30}
    assert driver.remaps[-1] == ('image', 'image_raw')
    assert result.unresolved == []

    found = instances(load(top))
    worker_b = found['/team/b/worker']
    assert worker_b.params == {'everywhere': 1, 'only_b': [1, 2],
                               'label': 'b'}
    assert worker_b.remaps[-1] == ('out', 'out_b')


def test_ros2_xml_arguments_reach_includes(tmp_path):
    write(tmp_path, 'inner.launch.xml', """
        <launch>
          <arg name="robot" default="inner_default"/>
          <node pkg="p" exec="n" name="$(var robot)_node"/>
        </launch>""")
    top = write(tmp_path, 'top.launch.xml', """
        <launch>
          <arg name="robot" default="outer_default"/>
          <include file="$(dirname)/inner.launch.xml"/>
        </launch>""")
    assert [i.name for i in load(top).instances] == ['outer_default_node']
    assert [i.name for i in load(top, arguments={'robot': 'cli'}).instances] \
        == ['cli_node']


def test_ros2_xml_self_referencing_args(tmp_path):
    top = write(tmp_path, 'top.launch.xml', """
        <launch>
          <arg name="a" default="$(var a)"/>
          <arg name="b" default="$(var c)"/>
          <arg name="c" default="$(var b)x"/>
          <node pkg="p" exec="n" name="$(var a)" namespace="$(var c)"/>
        </launch>""")
    result = load(top)
    node = result.instances[0]
    assert node.name is None and node.namespace is None
    assert "argument 'a' refers to itself" in '\n'.join(result.unresolved)


# ROS 2 YAML


def test_ros2_yaml_front_end():
    path = ROS2_PKG / 'launch' / 'navigation.launch.yaml'
    result = load(path, package_paths={'robot_bringup': ROS2_PKG})
    found = instances(result)
    planner = found['/planner']
    assert planner.remaps == [('map', '/map')]
    # /** applies; '/robot1/planner' does not; 'planner' means '/planner'
    assert planner.params == {'use_sim_time': False,
                              'only_for_a_root_planner': True,
                              'use_grid': True}
    assert planner.location.endswith('navigation.launch.yaml:8')
    local = found['/local/local_planner']
    assert local.location.endswith('navigation.launch.yaml:24')
    assert result.unresolved == []
    found = instances(load(path, arguments={'planner_name': 'global'},
                           package_paths={'robot_bringup': ROS2_PKG}))
    assert sorted(found) == ['/global']  # the local planner's if is false


def test_ros2_yaml_not_a_launch_file(tmp_path):
    path = write(tmp_path, 'x.launch.yaml', 'nodes: []\n')
    with pytest.raises(LaunchError, match='x.launch.yaml'):
        load(path)


# ROS 2 Python


def test_ros2_python_system():
    result = load(ROS2_PKG / 'launch' / 'robot.launch.py',
                  package_paths={'robot_bringup': ROS2_PKG})
    assert result.unresolved == []
    found = instances(result)
    assert sorted(found) == [
        '/monitor_0', '/monitor_1', '/robot1/camera_container',
        '/robot1/controller', '/robot1/front', '/robot1/gps',
        '/robot1/imu/imu', '/robot1/lidar', '/robot1/local/local_planner',
        '/robot1/planner', '/robot1/rear', '/robot1/vision/detector']
    controller = found['/robot1/controller']
    assert controller.remaps == [('/tf', 'tf'), ('cmd_vel', 'cmd_vel_safe'),
                                 ('odom', '/odom')]
    assert controller.params == {
        'rate': 50.0, 'base_frame': 'robot1/base_link', 'gains.p': 1.0,
        'gains.d': 0.1, 'use_sim_time': False, 'kp': 3.0}
    lidar = found['/robot1/lidar']
    # include arguments from a LaunchConfiguration and a literal
    assert lidar.params == {'rate': 15, 'frame_id': 'lidar_link',
                            'limits.min_range': 0.1,
                            'limits.max_range': 30}
    assert lidar.remaps == [('/tf', 'tf'), ('scan', 'scan_raw')]
    imu = found['/robot1/imu/imu']
    assert imu.remaps == [('/tf', 'tf'), ('data', 'data_raw')]
    assert imu.params == {'rate': 100}
    planner = found['/robot1/planner']
    assert planner.params == {'use_sim_time': False, 'expected_rate': 2.0,
                              'grid.resolution': 0.05, 'use_grid': True}
    front, rear = found['/robot1/front'], found['/robot1/rear']
    assert (front.kind, front.executable, front.params) == (
        'component', 'robot_camera::Driver', {'fps': 30})
    assert rear.params == {'fps': 15}
    assert found['/robot1/camera_container'].kind == 'container'
    assert found['/robot1/vision/detector'].kind == 'component'
    assert found['/monitor_1'].remaps == [('in', 'odom')]
    assert {Path(f).name for f in result.files} == {
        'robot.launch.py', 'sensors.launch.xml', 'nav_params.yaml',
        'navigation.launch.yaml', 'monitor.launch.py'}


def test_ros2_python_arguments_and_conditions():
    result = load(ROS2_PKG / 'launch' / 'robot.launch.py',
                  arguments={'robot': 'r2', 'nav': 'false',
                             'lidar_rate': '5'},
                  package_paths={'robot_bringup': ROS2_PKG})
    found = instances(result)
    assert '/r2/planner' not in found
    assert found['/r2/lidar'].params['rate'] == 5
    assert found['/r2/controller'].params['base_frame'] == 'r2/base_link'


PYTHON_LAUNCH = """
    import os

    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, OpaqueFunction
    from launch.conditions import LaunchConfigurationEquals, UnlessCondition
    from launch.substitutions import LaunchConfiguration, PythonExpression
    from launch_ros.actions import Node
    import my_helpers

    NAMESPACE = 'fleet'
    RATES = {'fast': 100, 'slow': 1}


    def make(name, **extra):
        return Node(package='pkg', executable='worker', name=name,
                    namespace=NAMESPACE, **extra)


    def generate_launch_description():
        ld = LaunchDescription()
        ld.add_action(DeclareLaunchArgument('mode', default_value='fast'))
        ld.add_action(make('known', parameters=[{'rate': RATES['fast']}]))
        if os.environ.get('FLEET_SIZE'):
            ld.add_action(make('maybe'))
        else:
            ld.add_action(make('otherwise'))
        for robot in my_helpers.robots():
            ld.add_action(make(robot))
        workers = [make(f'w{i}') for i in range(2)]
        ld.add_action(Node(package='pkg', executable=my_helpers.exe(),
                           name='unknown_exe'))
        ld.add_action(Node(
            package='pkg', executable='mode', name='fast_only',
            condition=LaunchConfigurationEquals('mode', 'fast')))
        ld.add_action(Node(
            package='pkg', executable='mode', name='not_fast',
            condition=UnlessCondition(PythonExpression(
                ["'", LaunchConfiguration('mode'), "' == 'fast'"]))))
        ld.add_action(OpaqueFunction(function=lambda context: []))
        for w in workers:
            ld.add_action(w)
        return ld
    """


def test_ros2_python_constructs(tmp_path):
    path = write(tmp_path, 'x.launch.py', PYTHON_LAUNCH)
    result = load(path, environ={'FLEET_SIZE': ''})
    names = [i.name for i in result.instances]
    assert names == ['known', 'otherwise', None, 'unknown_exe', 'fast_only',
                     'w0', 'w1']
    found = {i.name: i for i in result.instances}
    assert found['known'].params == {'rate': 100}
    assert found['known'].namespace == '/fleet'
    # a loop over a call not understood: one instance, name unknown
    looped = found[None]
    assert any('loop' in n for n in looped.unresolved)
    assert found['unknown_exe'].executable is None
    assert any('executable not known' in n
               for n in found['unknown_exe'].unresolved)
    notes = '\n'.join(result.unresolved)
    assert 'my_helpers.robots() not interpreted' in notes
    assert 'OpaqueFunction' in notes

    result = load(path, arguments={'mode': 'slow'}, environ={})
    names = [i.name for i in result.instances]
    assert 'fast_only' not in names and 'not_fast' in names


def test_ros2_python_unknown_condition_keeps_both_branches(tmp_path):
    path = write(tmp_path, 'x.launch.py', """
        from launch import LaunchDescription
        from launch_ros.actions import Node
        import socket


        def generate_launch_description():
            nodes = []
            if socket.gethostname() == 'robot':
                nodes.append(Node(package='p', executable='real', name='a'))
                rate = 10
            else:
                nodes.append(Node(package='p', executable='sim', name='a'))
                rate = 20
            nodes.append(Node(package='p', executable='user', name='u',
                              parameters=[{'rate': rate}]))
            return LaunchDescription(nodes)
        """)
    result = load(path)
    by_exe = {i.executable: i for i in result.instances}
    assert sorted(by_exe) == ['real', 'sim', 'user']
    assert result.instances[-1].executable == 'user'

    assert any('only when' in n for n in by_exe['real'].unresolved)
    assert any('only when' in n for n in by_exe['sim'].unresolved)
    assert by_exe['user'].params == {}
    assert any('rate' in n for n in by_exe['user'].unresolved)
    assert any('not known statically' in n for n in result.unresolved)


def test_ros2_python_alternatives_and_early_returns(tmp_path):
    path = write(tmp_path, 'x.launch.py', """
        import random

        from launch import LaunchDescription
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node


        def generate_launch_description():
            # always False in Python: read as not known statically
            if LaunchConfiguration('x') == 'true':
                nodes = [Node(package='p', executable='a')]
            else:
                nodes = [Node(package='p', executable='b')]
            if random.random() > 0.5:
                return LaunchDescription([Node(package='p',
                                               executable='early')])
            return LaunchDescription(nodes + [Node(package='p',
                                                   executable='late')])
        """)
    result = load(path)
    by_exe = {i.executable: i for i in result.instances}
    assert [i.executable for i in result.instances] == [
        'early', 'a', 'b', 'late']
    assert len(by_exe['early'].unresolved) == 1
    assert len(by_exe['a'].unresolved) == 2   # early return, first if
    assert len(by_exe['late'].unresolved) == 1
    assert 'is false' in by_exe['b'].unresolved[1]


def test_ros2_python_loop_over_unknown_values(tmp_path):
    path = write(tmp_path, 'x.launch.py', """
        from launch import LaunchDescription
        from launch_ros.actions import Node
        import helpers


        def generate_launch_description():
            nodes = [Node(package='p', executable='first')]
            for robot in helpers.robots():
                nodes = nodes + [Node(package='p', executable='looped',
                                      name=robot, namespace='fleet')]
            return LaunchDescription(nodes)
        """)
    result = load(path)
    first, looped = result.instances
    assert (first.executable, first.unresolved) == ('first', [])
    assert (looped.executable, looped.name, looped.namespace) == (
        'looped', None, '/fleet')
    assert 'created in a loop' in looped.unresolved[0]


def test_ros2_python_top_level_code_is_never_run(tmp_path):
    marker = tmp_path / 'written_at_import'
    inside = tmp_path / 'written_in_function'
    path = write(tmp_path, 'x.launch.py', f"""
        import subprocess

        from launch import LaunchDescription
        from launch_ros.actions import Node

        with open({str(marker)!r}, 'w') as f:
            f.write('executed')
        open({str(marker)!r}, 'w').write('executed')
        subprocess.run(['touch', {str(marker)!r}])
        EXE = __import__('os').system('touch ' + {str(marker)!r})


        def generate_launch_description():
            open({str(inside)!r}, 'w').write('executed')
            exec("open({str(inside)!r}, 'w')")
            return LaunchDescription([Node(package='p', executable='n')])
        """)
    result = load(path)
    assert not marker.exists() and not inside.exists()
    assert [i.executable for i in result.instances] == ['n']
    notes = '\n'.join(result.unresolved)
    assert 'module-level With statement not interpreted' in notes
    assert 'open() not interpreted' in notes


def test_ros2_python_includes_and_sources(tmp_path):
    write(tmp_path, 'pkg/launch/child.launch.py', """
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('name', default_value='child'),
                Node(package='p', executable='c',
                     name=LaunchConfiguration('name'),
                     remappings=[('in', LaunchConfiguration('topic',
                                                            default='x'))]),
            ])
        """)
    path = write(tmp_path, 'pkg/launch/top.launch.py', """
        import os

        from ament_index_python.packages import get_package_share_directory
        from launch import LaunchDescription
        from launch.actions import GroupAction, IncludeLaunchDescription
        from launch.launch_description_sources import (
            PythonLaunchDescriptionSource)
        from launch.substitutions import PathJoinSubstitution
        from launch.substitutions import ThisLaunchFileDir
        from launch_ros.actions import PushRosNamespace
        from launch_ros.substitutions import FindPackageShare


        def generate_launch_description():
            by_dir = IncludeLaunchDescription(PythonLaunchDescriptionSource(
                [ThisLaunchFileDir(), '/child.launch.py']),
                launch_arguments=[('name', 'one')])
            by_share = IncludeLaunchDescription(
                PythonLaunchDescriptionSource(PathJoinSubstitution([
                    FindPackageShare('pkg'), 'launch', 'child.launch.py'])),
                launch_arguments={'name': 'two', 'topic': 'y'}.items())
            by_ament = IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(
                    get_package_share_directory('pkg'), 'launch',
                    'child.launch.py')))
            missing = IncludeLaunchDescription(
                PythonLaunchDescriptionSource('/no/such/file.launch.py'))
            return LaunchDescription([
                by_dir,
                GroupAction([PushRosNamespace('g'), by_share]),
                by_ament, missing])
        """)
    result = load(path, package_paths={'pkg': tmp_path / 'pkg'})
    found = instances(result)
    assert sorted(found) == ['/child', '/g/two', '/one']
    assert found['/g/two'].remaps == [('in', 'y')]
    assert found['/one'].remaps == [('in', 'x')]
    assert 'file.launch.py not found' in '\n'.join(result.unresolved)


def test_ros2_python_malformed(tmp_path):
    path = write(tmp_path, 'bad.launch.py', 'def generate(:\n')
    with pytest.raises(LaunchError, match='bad.launch.py: not valid Python'):
        load(path)


# robustness


@pytest.mark.parametrize('name,text', [
    ('a.launch', """
        <launch>
          <node pkg="p" type="t" name="n"/>
          <include file="$(dirname)/b.launch"/>
        </launch>"""),
    ('a.launch.xml', """
        <launch>
          <node pkg="p" exec="t" name="n"/>
          <include file="$(dirname)/b.launch.xml"/>
        </launch>"""),
    ('a.launch.py', """
        import os
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import AnyLaunchDescriptionSource
        from launch_ros.actions import Node

        def generate_launch_description():
            return LaunchDescription([
                Node(package='p', executable='t', name='n'),
                IncludeLaunchDescription(AnyLaunchDescriptionSource(
                    os.path.join(os.path.dirname(__file__), 'b.launch.yaml')))])
        """),
])
def test_include_cycles_stop_with_a_note(tmp_path, name, text):
    first = write(tmp_path, name, text)
    other = {'a.launch': ('b.launch', """
                 <launch><include file="$(dirname)/a.launch"/></launch>"""),
             'a.launch.xml': ('b.launch.xml', """
                 <launch><include file="$(dirname)/a.launch.xml"/></launch>"""),
             'a.launch.py': ('b.launch.yaml', """
                 launch:
                 - include:
                     file: $(dirname)/a.launch.py
                 """)}[name]
    write(tmp_path, *other)
    result = load(first)
    assert [i.name for i in result.instances] == ['n']
    assert any('include cycle' in n for n in result.unresolved)


def test_include_depth_limit(tmp_path):
    levels = MAX_INCLUDE_DEPTH + 10
    for index in range(levels):
        write(tmp_path, f'l{index}.launch', f"""
            <launch>
              <node pkg="p" type="t" name="n{index}"/>
              <include file="$(dirname)/l{index + 1}.launch"/>
            </launch>""")
    result = load(tmp_path / 'l0.launch')
    assert len(result.instances) == MAX_INCLUDE_DEPTH
    assert any('nested deeper than' in n for n in result.unresolved)


def test_include_fan_out_is_bounded(tmp_path):
    # each level includes the next one twice: 2**30 reads without a budget
    for index in range(30):
        write(tmp_path, f'l{index}.launch', f"""
            <launch>
              <include file="$(dirname)/l{index + 1}.launch"/>
              <include file="$(dirname)/l{index + 1}.launch"/>
            </launch>""")
    write(tmp_path, 'l30.launch', '<launch/>')
    started = time.monotonic()
    result = load(tmp_path / 'l0.launch')
    assert time.monotonic() - started < 30
    assert any('more than' in n and 'includes' in n
               for n in result.unresolved)


BILLION_LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE launch [
  <!ENTITY lol "lol">
  <!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
  <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
  <!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
  <!ENTITY lol5 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;">
  <!ENTITY lol6 "&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;">
  <!ENTITY lol7 "&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;">
  <!ENTITY lol8 "&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;">
  <!ENTITY lol9 "&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;">
]>
<launch><node pkg="p" type="t" name="&lol9;"/></launch>
"""

XXE = """<?xml version="1.0"?>
<!DOCTYPE launch [<!ENTITY secret SYSTEM "file:///etc/passwd">]>
<launch><node pkg="p" type="t" name="&secret;"/></launch>
"""


@pytest.mark.parametrize('text', [BILLION_LAUGHS, XXE])
@pytest.mark.parametrize('name', ['bomb.launch', 'bomb.launch.xml'])
def test_entity_bombs_and_xxe_are_refused(tmp_path, text, name):
    path = write(tmp_path, name, text)
    with pytest.raises(LaunchError) as error:
        load(path)
    message = one_sentence(error.value)
    assert str(path) in message and 'refused' in message


def test_entity_bomb_in_an_included_file(tmp_path):
    write(tmp_path, 'bomb.launch', BILLION_LAUGHS)
    top = write(tmp_path, 'top.launch', """
        <launch><include file="$(dirname)/bomb.launch"/></launch>""")
    with pytest.raises(LaunchError, match='bomb.launch: refused'):
        load(top)


@pytest.mark.parametrize('name,text,what', [
    ('bad.launch', '<launch><node pkg="p" type="t" name="n"></launch>',
     'malformed XML'),
    ('bad.launch.xml', '<launch><node pkg="p" exec="t"', 'malformed XML'),
    ('bad.launch.yaml', 'launch:\n  - node: {pkg: [\n', 'malformed YAML'),
    ('bad.launch', '', 'malformed XML'),
    ('bad.launch', '<robot/>', 'not <launch>'),
])
def test_malformed_files(tmp_path, name, text, what):
    path = write(tmp_path, name, text)
    with pytest.raises(LaunchError) as error:
        load(path)
    message = one_sentence(error.value)
    assert str(path) in message and what in message


def test_malformed_param_file_names_the_file(tmp_path):
    write(tmp_path, 'p.yaml', 'a: [1, 2\n')
    top = write(tmp_path, 'top.launch', """
        <launch>
          <node pkg="p" type="t" name="n">
            <rosparam file="$(dirname)/p.yaml"/>
          </node>
        </launch>""")
    with pytest.raises(LaunchError, match=r'p\.yaml: malformed YAML'):
        load(top)


def test_yaml_alias_bomb_is_refused(tmp_path):
    lines = ['a0: &a0 [x, x, x, x, x, x, x, x, x]']
    for i in range(1, 10):
        refs = ', '.join([f'*a{i - 1}'] * 9)
        lines.append(f'a{i}: &a{i} [{refs}]')
    write(tmp_path, 'p.yaml', '\n'.join(lines) + '\n')
    top = write(tmp_path, 'top.launch', """
        <launch>
          <rosparam file="$(dirname)/p.yaml"/>
          <node pkg="p" type="t" name="n"/>
        </launch>""")
    with pytest.raises(LaunchError, match='too many values'):
        load(top)


def test_top_level_file_not_found(tmp_path):
    with pytest.raises(LaunchError) as error:
        load(tmp_path / 'nope.launch')
    assert 'launch file not found' in one_sentence(error.value)


def test_deeply_nested_groups_and_expressions(tmp_path):
    depth = 300
    xml = '<launch>' + '<group>' * depth + '<node pkg="p" type="t" name="n"/>' \
        + '</group>' * depth + '</launch>'
    result = load(write(tmp_path, 'deep.launch', xml))
    assert any('nested deeper' in n for n in result.unresolved)
    code = ('from launch import LaunchDescription\n'
            'X = ' + ' + '.join(['1'] * 5000) + '\n'
            'Y = ' + '[' * 90 + ']' * 90 + '\n'
            'def generate_launch_description():\n'
            '    return LaunchDescription([])\n')
    path = write(tmp_path, 'deep.launch.py', code)
    try:
        result = load(path)
    except LaunchError as e:
        one_sentence(e)
    else:
        assert isinstance(result, LaunchResult)


def test_file_kind_detection(tmp_path):
    assert file_kind('a.launch', '<launch><node pkg="a" type="b"/></launch>') \
        == 'ros1'
    assert file_kind('a.xml', '<launch><node pkg="a" exec="b"/></launch>') \
        == 'ros2'
    assert file_kind('a.launch.xml', '<launch><rosparam/></launch>') == 'ros1'
    assert file_kind('a.launch', '<launch><group/></launch>') == 'ros1'
    assert file_kind('a.launch.xml', '<launch><group/></launch>') == 'ros2'
    assert file_kind('a.launch.py', '') == 'python'
    assert file_kind('a.launch.yaml', '') == 'yaml'


def test_python_work_is_bounded(tmp_path):
    path = write(tmp_path, 'x.launch.py', """
        from launch import LaunchDescription
        from launch.actions import GroupAction
        from launch_ros.actions import Node


        def generate_launch_description():
            level = [Node(package='p', executable='n')] * 200
            for _ in range(5):
                level = [GroupAction(level)] * 200
            text = f'{1:999999999}' + 'x'.replace('', 'y' * 99999)
            big = [i for i in range(1000) for j in range(1000)]
            while True:
                level.append(level)
            return LaunchDescription(level)
        """)
    started = time.monotonic()
    result = load(path)
    assert time.monotonic() - started < 30
    notes = '\n'.join(result.unresolved)
    assert 'format spec not interpreted' in notes
    assert 'too many steps' in notes or 'launch actions' in notes


def test_yaml_launch_alias_bomb_is_refused(tmp_path):
    lines = ['x0: &x0 [{node: {pkg: p, exec: e}}, {node: {pkg: p, exec: e}}]']
    for i in range(1, 30):
        lines.append(f'x{i}: &x{i} [{{group: {{children: *x{i - 1}}}}}, '
                     f'{{group: {{children: *x{i - 1}}}}}]')
    lines.append('launch: *x29')
    path = write(tmp_path, 'bomb.launch.yaml', '\n'.join(lines) + '\n')
    with pytest.raises(LaunchError, match='too many values'):
        load(path)


def test_parameter_file_patterns_cannot_backtrack(tmp_path):
    write(tmp_path, 'p.yaml', '/' + '**/' * 40 + 'x*y*z*w*v:\n'
          '  ros__parameters:\n    a: 1\n/**:\n  ros__parameters:\n'
          '    b: 2\n')
    path = write(tmp_path, 'x.launch.xml', """
        <launch>
          <node pkg="p" exec="e" name="xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxq"
                namespace="/a/b/c/d/e/f/g/h/i/j/k/l/m/n/o/p/q/r/s/t/u/v/w">
            <param from="$(dirname)/p.yaml"/>
          </node>
        </launch>""")
    started = time.monotonic()
    assert load(path).instances[0].params == {'b': 2}
    assert time.monotonic() - started < 5


# one arithmetic: $(eval) and Python launch files compute alike

def test_eval_and_python_launch_arithmetic_agree(tmp_path):
    expressions = {'big': '2 ** 100', 'ratio': '7 / 2', 'floor': '7 // 2',
                   'huge': '10 ** 400', 'text': "'ab' * 3"}
    write(tmp_path, 'a.launch.xml', '<launch>\n  <node pkg="p" exec="e" '
          'name="n">\n' + ''.join(
              f'    <param name="{name}" value="$(eval {value})"/>\n'
              for name, value in expressions.items()) +
          '  </node>\n</launch>\n')
    write(tmp_path, 'a.launch.py', """
        from launch import LaunchDescription
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([Node(
                package='p', executable='e', name='n', parameters=[{
    """ + ''.join(f"            '{name}': {value},\n"
                  for name, value in expressions.items()) + """
                }])])
    """)
    xml = load(tmp_path / 'a.launch.xml').instances[0]
    python = load(tmp_path / 'a.launch.py').instances[0]
    # written by hand: what Python computes, and no number beyond 1e308
    expected = {'big': 2 ** 100, 'ratio': 3.5, 'floor': 3,
                'text': 'ababab'}
    assert {k: v for k, v in xml.params.items() if k != 'huge'} == expected
    assert {k: v for k, v in python.params.items() if k != 'huge'} == \
        expected
    assert not isinstance(xml.params.get('huge'), int)
    assert not isinstance(python.params.get('huge'), int)


def test_a_composable_node_outside_a_container_is_a_note(tmp_path):
    # launch itself refuses it; the rest of the file is still read
    path = write(tmp_path, 'stray.launch.py', """
        from launch import LaunchDescription
        from launch_ros.actions import Node
        from launch_ros.descriptions import ComposableNode

        def generate_launch_description():
            return LaunchDescription([
                ComposableNode(package='demo', plugin='demo::Talker',
                               name='talker'),
                Node(package='demo', executable='listener', name='listener'),
            ])
        """)
    result = load(path)
    assert sorted(instances(result)) == ['/listener']
    assert any('ComposableNode outside a container' in note
               for note in result.unresolved)
