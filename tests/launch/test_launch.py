# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Launch front ends: ROS 1 XML, ROS 2 XML, YAML and Python, read statically."""

from pathlib import Path
import time

from colcon_rsia.launch import file_kind
from colcon_rsia.launch import LaunchError
from launch_helpers import instances
from launch_helpers import load
from launch_helpers import ROS1_PKG
from launch_helpers import ROS2_PKG
from launch_helpers import write
import pytest


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
