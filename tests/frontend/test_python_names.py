# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Python topic names from parameters, constants and string building."""

from colcon_rsia.package.python_analysis import analyze_python_package
from colcon_rsia.render.graph import graph_to_json
from colcon_rsia.system.load import load_system
import pytest

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>names</name>
  <version>0.0.1</version>
  <description>test</description>
  <maintainer email="a@b.c">a</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""

CONSTANTS = """
BASE = 'robot'
"""

# a ROS 1 node: parameters, module constants, string building
RELAY = """#!/usr/bin/env python3
import rospy
from std_msgs.msg import String
from names_lib.constants import BASE

SCAN = 'scan'
PREFIX = 'robot'


def start(prefix_given):
    rospy.Publisher('%s/free' % prefix_given, String, queue_size=1)


def main():
    rospy.init_node('relay')
    rospy.Subscriber(rospy.get_param('~input', 'chatter'), String,
                     lambda msg: None)
    out = rospy.get_param('output', 'echo')
    rospy.Publisher(out, String, queue_size=1)
    rospy.Publisher(SCAN, String, queue_size=1)
    rospy.Publisher('%s/cmd_vel' % PREFIX, String, queue_size=1)
    rospy.Publisher(f'{PREFIX}/odom', String, queue_size=1)
    rospy.Publisher('{}/{}'.format(BASE, SCAN), String, queue_size=1)
    rospy.Publisher('{name}/{n}'.format(name=PREFIX, n=2), String,
                    queue_size=1)
    rospy.Publisher(PREFIX + '/joint_states', String, queue_size=1)
    rospy.Publisher('%d/bad' % 3, String, queue_size=1)
    start(rospy.get_name())
    rospy.spin()


if __name__ == '__main__':
    main()
"""

# a ROS 2 node: declared parameters and a class constant
FILTER = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Filter(Node):
    STATS = 'filter_stats'

    def __init__(self):
        super().__init__('filter')
        self.declare_parameter('output', 'filtered')
        self.create_subscription(
            String, self.declare_parameter('input', 'scan').value,
            self.on_input, 10)
        topic = self.get_parameter('output').get_parameter_value() \\
            .string_value
        self.out = self.create_publisher(String, topic, 10)
        self.stats = self.create_publisher(String, self.STATS, 10)

    def on_input(self, msg):
        self.out.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(Filter())


if __name__ == '__main__':
    main()
"""

# ROS 1: names built around a parameter's value, a parameter name and a
# default held in constants, a parameter without a default
AROUND = """#!/usr/bin/env python3
import rospy
from std_msgs.msg import String

NS_PARAM = '~robot_ns'
NS_DEFAULT = 'base'


def main():
    rospy.init_node('around')
    ns = rospy.get_param(NS_PARAM, NS_DEFAULT)
    rospy.Publisher('%s/cmd_vel' % ns, String, queue_size=1)
    rospy.Publisher('{}/odom'.format(ns), String, queue_size=1)
    rospy.Publisher('/' + ns + '/status', String, queue_size=1)
    rospy.Subscriber(f'{ns}/goal', String, lambda msg: None)
    required = rospy.get_param('~required_topic')
    rospy.Publisher(required, String, queue_size=1)
    # two parameters in one name: which one is not one value
    other = rospy.get_param('~other', 'x')
    rospy.Publisher(ns + '/' + other, String, queue_size=1)
    rospy.spin()


if __name__ == '__main__':
    main()
"""

# ROS 2: declared parameters, read where declared or later, with defaults
# held in variables and constants
DECLARED = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node
from std_msgs.msg import String

PREFIX_PARAM = 'prefix'


class Declared(Node):
    DEFAULT_SCAN = 'scan_raw'

    def __init__(self):
        super().__init__('declared')
        default_prefix = 'robot'
        self.declare_parameter(PREFIX_PARAM, default_prefix)
        prefix = self.get_parameter(PREFIX_PARAM).value
        self.create_publisher(String, prefix + '/state', 10)
        self.create_publisher(String, f'{prefix}/pose', 10)
        scan = self.declare_parameter('scan', self.DEFAULT_SCAN) \\
            .get_parameter_value().string_value
        self.create_subscription(String, scan, self.on_scan, 10)
        self.create_publisher(
            String, self.get_parameter('undeclared').value, 10)

    def on_scan(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Declared())


if __name__ == '__main__':
    main()
"""

# ROS 2: several parameters declared at once, with and without namespace
DECLARED_MANY = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Many(Node):
    def __init__(self):
        super().__init__('many')
        self.declare_parameters(
            namespace='',
            parameters=[('input', 'points'), ('output', 'filtered_points'),
                        ('rate', 10.0)])
        self.declare_parameters('topics', [('debug', 'debug_out')])
        self.create_subscription(
            String, self.get_parameter('input').value, self.on_input, 10)
        self.create_publisher(
            String,
            self.get_parameter('output').get_parameter_value().string_value,
            10)
        self.create_publisher(
            String, self.get_parameter('topics.debug').value, 10)

    def on_input(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Many())


if __name__ == '__main__':
    main()
"""

LAUNCH = """<launch>
  <node pkg="names" type="relay" name="relay">
    <param name="input" value="remapped_input"/>
    <param name="output" value="not_private"/>
  </node>
  <node pkg="names" type="around" name="around">
    <param name="robot_ns" value="arm"/>
  </node>
</launch>
"""


@pytest.fixture(scope='module')
def package(tmp_path_factory):
    root = tmp_path_factory.mktemp('names') / 'names'
    files = {
        'package.xml': PACKAGE_XML,
        'CMakeLists.txt': 'cmake_minimum_required(VERSION 3.10)\n'
                          'project(names)\nfind_package(catkin REQUIRED)\n'
                          'catkin_package()\n',
        'src/names_lib/__init__.py': '',
        'src/names_lib/constants.py': CONSTANTS,
        'scripts/relay': RELAY,
        'scripts/filter': FILTER,
        'scripts/around': AROUND,
        'scripts/declared': DECLARED,
        'scripts/declared_many': DECLARED_MANY,
        'launch/relay.launch': LAUNCH,
    }
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        if relative.startswith('scripts/'):
            path.chmod(0o755)
    return root


@pytest.fixture(scope='module')
def summary(package, tmp_path_factory):
    return analyze_python_package(
        name='names', path=str(package),
        build_base=str(tmp_path_factory.mktemp('build')))


def _topics(summary, executable, role='publishers'):
    node = next(n for n in summary.nodes if n.executable == executable)
    return {(t.topic, t.topic_is_literal,
             (t.topic_param.name, t.topic_param.default,
              t.topic_param.namespace) if t.topic_param else None)
            for t in getattr(node, role)}


def _affixes(summary, executable, role='publishers'):
    node = next(n for n in summary.nodes if n.executable == executable)
    return {t.topic: (t.topic_param.name, t.topic_param.prefix,
                      t.topic_param.suffix) if t.topic_param else None
            for t in getattr(node, role)}


def test_rospy_names(summary):
    assert _topics(summary, 'relay') == {
        ('out', False, ('output', 'echo', '')),
        ('scan', True, None),
        ('robot/cmd_vel', True, None),
        ('robot/odom', True, None),
        ('robot/scan', True, None),
        ('robot/2', True, None),
        ('robot/joint_states', True, None),
        # only %s is formatted; a parameter of a function is not known
        ("'%d/bad' % 3", False, None),
        ("'%s/free' % prefix_given", False, None),
    }
    assert _topics(summary, 'relay', 'subscribers') == {
        ("rospy.get_param('~input', 'chatter')", False,
         ('input', 'chatter', '~'))}


def test_rclpy_names(summary):
    assert _topics(summary, 'filter') == {
        ('topic', False, ('output', 'filtered', '~')),
        ('filter_stats', True, None)}
    assert _topics(summary, 'filter', 'subscribers') == {
        ("self.declare_parameter('input', 'scan').value", False,
         ('input', 'scan', '~'))}


def _resolved(system, node_name):
    node = next(n for n in graph_to_json(system)['nodes']
                if n['name'] == node_name)
    # names not known resolve to None
    return sorted((t['resolved'] or '-') for t in
                  node['publishers'] + node['subscribers'])


def test_names_resolve_and_connect(summary, package):
    system = load_system([summary])
    assert _resolved(system, '/relay') == [
        '-', '-', '/chatter', '/echo', '/robot/2', '/robot/cmd_vel',
        '/robot/joint_states', '/robot/odom', '/robot/scan', '/scan']
    assert _resolved(system, '/filter') == [
        '/filter_stats', '/filtered', '/scan']
    graph = graph_to_json(system)
    scan = next(t for t in graph['topics'] if t['name'] == '/scan')
    assert scan['publishers'] == ['names/relay']
    assert scan['subscribers'] == ['names/filter']


def test_private_parameters_of_the_launch_file_name_topics(summary, package):
    system = load_system(
        [summary], launch=[str(package / 'launch' / 'relay.launch')],
        package_paths={'names': str(package)})
    resolved = _resolved(system, '/relay')
    # ~input is set by the launch file; `output` is not private: its
    # default stays
    assert '/remapped_input' in resolved
    assert '/chatter' not in resolved
    assert '/echo' in resolved


def test_names_built_around_a_parameter(summary):
    # the parameter's name and default come from module constants; the
    # text joined around its value is kept with it
    assert _affixes(summary, 'around') == {
        "'%s/cmd_vel' % ns": ('robot_ns', '', '/cmd_vel'),
        "'{}/odom'.format(ns)": ('robot_ns', '', '/odom'),
        "'/' + ns + '/status'": ('robot_ns', '/', '/status'),
        'required': ('required_topic', '', ''),
        # two parameters: no one value to substitute
        "ns + '/' + other": None,
    }
    assert _affixes(summary, 'around', 'subscribers') == {
        "f'{ns}/goal'": ('robot_ns', '', '/goal')}
    system = load_system([summary])
    assert _resolved(system, '/around') == [
        '-', '-', '/base/cmd_vel', '/base/goal', '/base/odom',
        '/base/status']


def test_names_around_a_parameter_take_the_launch_files_value(
        summary, package):
    system = load_system(
        [summary], launch=[str(package / 'launch' / 'relay.launch')],
        package_paths={'names': str(package)})
    assert _resolved(system, '/around') == [
        '-', '-', '/arm/cmd_vel', '/arm/goal', '/arm/odom', '/arm/status']


def test_declared_parameters_with_defaults_in_variables(summary):
    # declare_parameter(CONSTANT, variable) then get_parameter(CONSTANT):
    # the default of the declaration; a class constant as default
    assert _affixes(summary, 'declared') == {
        "prefix + '/state'": ('prefix', '', '/state'),
        "f'{prefix}/pose'": ('prefix', '', '/pose'),
        "self.get_parameter('undeclared').value": ('undeclared', '', ''),
    }
    assert _topics(summary, 'declared', 'subscribers') == {
        ('scan', False, ('scan', 'scan_raw', '~'))}
    system = load_system([summary])
    assert _resolved(system, '/declared') == [
        '-', '/robot/pose', '/robot/state', '/scan_raw']


def test_a_parameter_without_default_is_unknown_with_a_note(summary):
    notes = [d for d in summary.diagnostics if 'no default' in d]
    assert notes == [
        "scripts/around:17: note: the topic 'required' is the value of "
        "the parameter '~required_topic', which has no default: not known "
        'unless a launch file sets it',
        'scripts/declared:22: note: the topic '
        '"self.get_parameter(\'undeclared\').value" is the value of the '
        "parameter '~undeclared', which has no default: not known unless "
        'a launch file sets it']


def test_parameters_declared_together(summary):
    assert _topics(summary, 'declared_many') == {
        ("self.get_parameter('output').get_parameter_value().string_value",
         False, ('output', 'filtered_points', '~')),
        ("self.get_parameter('topics.debug').value", False,
         ('topics.debug', 'debug_out', '~'))}
    assert _topics(summary, 'declared_many', 'subscribers') == {
        ("self.get_parameter('input').value", False,
         ('input', 'points', '~'))}
    system = load_system([summary])
    assert _resolved(system, '/many') == [
        '/debug_out', '/filtered_points', '/points']
