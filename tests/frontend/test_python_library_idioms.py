# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Python endpoints made by library classes and the package's helpers.

Each script is a node; the expectations are written from reading the
scripts and the libraries' documented behaviour.
"""

from colcon_rsia.package.python_analysis import analyze_python_package
from colcon_rsia.render.graph import graph_to_json
from colcon_rsia.system.load import load_system
import pytest

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>idioms</name>
  <version>0.0.1</version>
  <description>test</description>
  <maintainer email="a@b.c">a</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""

# ROS 1: the updater publishes where update() is called, here in a loop
# paced by a Rate; a DiagnosedPublisher publishes through the publisher it
# wraps
DIAG_LOOP = """#!/usr/bin/env python3
import rospy
import diagnostic_updater
from std_msgs.msg import String


def check(stat):
    return stat


if __name__ == '__main__':
    rospy.init_node('diag_loop')
    rospy.Subscriber('input', String, lambda msg: None)
    updater = diagnostic_updater.Updater()
    updater.add('check', check)
    pub = rospy.Publisher('chatter', String, queue_size=1)
    freq = diagnostic_updater.FrequencyStatusParam({'min': 5, 'max': 15})
    diagnosed = diagnostic_updater.DiagnosedPublisher(
        pub, updater, freq, diagnostic_updater.TimeStampStatusParam())
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        diagnosed.publish(String())
        updater.update()
        rate.sleep()
"""

# ROS 1: the updater forced from a subscription callback
DIAG_CALLBACK = """#!/usr/bin/env python3
import rospy
from diagnostic_updater import Updater
from std_msgs.msg import String


class Watcher(object):
    def __init__(self):
        self.updater = Updater()
        rospy.Subscriber('events', String, self.on_event)

    def on_event(self, msg):
        self.updater.force_update()


if __name__ == '__main__':
    rospy.init_node('diag_callback')
    Watcher()
    rospy.spin()
"""

# ROS 2: Updater(node, period) publishes from a timer of its own (every
# `period` seconds, 1 s by default); update() called from a subscription
# callback publishes there too
DIAG_ROS2 = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node
import diagnostic_updater
from std_msgs.msg import String

PERIOD = 0.25


class Monitor(Node):
    def __init__(self):
        super().__init__('monitor')
        self.updater = diagnostic_updater.Updater(self, PERIOD)
        self.updater.add('check', lambda stat: stat)
        self.create_subscription(String, 'events', self.on_event, 10)
        self.manual = diagnostic_updater.Updater(node=self)

    def on_event(self, msg):
        self.manual.update()


def main():
    rclpy.init()
    rclpy.spin(Monitor())


if __name__ == '__main__':
    main()
"""

# the package's library re-exports its modules' names with star imports;
# `Relay` is both a submodule and the class it defines (the package's
# __init__.py makes the name the class, as when run)
LIB_INIT = """from .Relay import *
from .names import *
"""

LIB_NAMES = """__all__ = ['INPUT']
INPUT = 'relay_in'
OUTPUT = 'not_exported'
"""

LIB_RELAY = """import rospy
from std_msgs.msg import String


class Relay(object):
    def __init__(self):
        self.pub = rospy.Publisher('relay_out', String, queue_size=1)

    def forward(self, msg):
        self.pub.publish(msg)
"""

STAR_PACKAGE = """#!/usr/bin/env python3
import rospy
from idioms_lib import Relay, INPUT
from std_msgs.msg import String

if __name__ == '__main__':
    rospy.init_node('star_package')
    relay = Relay()
    rospy.Subscriber(INPUT, String, relay.forward)
    rospy.spin()
"""

# rospy's names through a star import
STAR_ROSPY = """#!/usr/bin/env python3
from rospy import *
from std_msgs.msg import String

if __name__ == '__main__':
    init_node('star_rospy')
    Subscriber('ticks', String, lambda msg: None)
    out = Publisher('paced', String, queue_size=1)
    rate = Rate(5)
    while not is_shutdown():
        out.publish(String())
        rate.sleep()
"""

# ROS 1: an interactive marker server subscribes <topic_ns>/feedback and
# calls the marker's and the menu's callbacks from it: a publish in one is
# input-driven
MARKERS_ROS1 = """#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist
from interactive_markers.interactive_marker_server import *
from interactive_markers.menu_handler import MenuHandler
from visualization_msgs.msg import InteractiveMarker


def on_feedback(feedback):
    pass


def on_menu(feedback):
    cmd_pub.publish(Twist())


if __name__ == '__main__':
    rospy.init_node('markers')
    server = InteractiveMarkerServer('marker_server')
    cmd_pub = rospy.Publisher('cmd_vel', Twist, queue_size=1)
    menu = MenuHandler()
    menu.insert('stop', callback=on_menu)
    server.insert(InteractiveMarker(), on_feedback)
    menu.apply(server, 'marker')
    server.applyChanges()
    rospy.spin()
"""

# ROS 2: InteractiveMarkerServer(node, topic_ns), callbacks by keyword; the
# node publishes from a timer only: the feedback input does not drive it
MARKERS_ROS2 = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from interactive_markers import InteractiveMarkerServer
from visualization_msgs.msg import InteractiveMarker

SERVER = 'goal_marker'


class GoalMarker(Node):
    def __init__(self):
        super().__init__('goal_marker_node')
        self.goal = None
        self.pub = self.create_publisher(Twist, 'cmd_vel', 10)
        self.server = InteractiveMarkerServer(self, SERVER)
        self.server.insert(InteractiveMarker(),
                           feedback_callback=self.on_feedback)
        self.server.setCallback('other', feedback_callback=self.on_other)
        self.create_timer(0.1, self.tick)

    def on_feedback(self, feedback):
        self.goal = feedback.pose

    def on_other(self, feedback):
        self.goal = None

    def tick(self):
        self.pub.publish(Twist())


def main():
    rclpy.init()
    rclpy.spin(GoalMarker())


if __name__ == '__main__':
    main()
"""

# helpers of the package that make endpoints from their parameters: each
# call is an endpoint named by its arguments (or the defaults)
LIB_ENDPOINTS = """import rospy
from std_msgs.msg import String


class StateWatch(object):
    def __init__(self, name, topic, suffix='state'):
        self.name = name
        self.topic = f'{topic}/{suffix}'
        self.latest = None

    def start(self):
        self.sub = rospy.Subscriber(self.topic, String, self.on_state)

    def on_state(self, msg):
        self.latest = msg


def make_status_publisher(ns, queue=1):
    return rospy.Publisher(ns + '/status', String, queue_size=queue)
"""

WATCH_A = """#!/usr/bin/env python3
import rospy
from idioms_lib.endpoints import StateWatch, make_status_publisher

ARM = '/arm'

if __name__ == '__main__':
    rospy.init_node('watch_a')
    arm = StateWatch('arm', ARM)
    arm.start()
    base = StateWatch('base', '/base', suffix='mode')
    base.start()
    status = make_status_publisher('watch_a')
    rospy.spin()
"""

WATCH_B = """#!/usr/bin/env python3
import rospy
from idioms_lib.endpoints import StateWatch

if __name__ == '__main__':
    rospy.init_node('watch_b')
    lift = StateWatch('lift', topic='/lift')
    lift.start()
    rospy.spin()
"""

# the argument is not known: the helper's endpoint stays, unnamed
WATCH_C = """#!/usr/bin/env python3
import sys
import rospy
from idioms_lib.endpoints import StateWatch

if __name__ == '__main__':
    rospy.init_node('watch_c')
    other = StateWatch('other', sys.argv[1])
    other.start()
    rospy.spin()
"""

# ROS 2: a helper class given the node, each object kept in a list; the
# message type is a parameter too
MONITORS = """#!/usr/bin/env python3
import rclpy
import rclpy.node
from std_msgs.msg import String
from std_msgs.msg import Bool


class TopicMonitor:
    def __init__(self, node, topic_name, topic_type):
        self.sub = node.create_subscription(
            topic_type, topic_name, self.callback, 1)

    def callback(self, msg):
        pass


class Monitors(rclpy.node.Node):
    def __init__(self):
        super().__init__('monitors')
        self.monitors = []
        self.monitors.append(TopicMonitor(self, '/api/state', String))
        self.monitors.append(TopicMonitor(self, '/api/ready', Bool))


if __name__ == '__main__':
    rclpy.init()
    rclpy.spin(Monitors())
"""

# a lambda is a helper too: called with a topic, it names its publisher
LAMBDA_HELPER = """#!/usr/bin/env python3
import rospy
from std_msgs.msg import String

make = lambda topic: rospy.Publisher(topic, String, queue_size=1)

if __name__ == '__main__':
    rospy.init_node('lambda_helper')
    out = make('made_by_lambda')
    rospy.spin()
"""

# a module of a package imports a name from the package, whose
# __init__.py star-imports that module's names: the name is the class
CYCLE_INIT = """from .core import *
from .tools import *
"""

CYCLE_CORE = """import rospy
from std_msgs.msg import String


class Core(object):
    def __init__(self):
        self.pub = rospy.Publisher('core_out', String, queue_size=1)
"""

CYCLE_TOOLS = """from cycle_lib import Core


def make_core():
    return Core()
"""

CYCLE = """#!/usr/bin/env python3
import rospy
from cycle_lib import Core

if __name__ == '__main__':
    rospy.init_node('cycle')
    core = Core()
    rospy.spin()
"""


@pytest.fixture(scope='module')
def package(tmp_path_factory):
    root = tmp_path_factory.mktemp('idioms') / 'idioms'
    files = {
        'package.xml': PACKAGE_XML,
        'CMakeLists.txt': 'cmake_minimum_required(VERSION 3.10)\n'
                          'project(idioms)\nfind_package(catkin REQUIRED)\n'
                          'catkin_package()\n',
        'scripts/diag_loop': DIAG_LOOP,
        'scripts/diag_callback': DIAG_CALLBACK,
        'scripts/diag_ros2': DIAG_ROS2,
        'src/idioms_lib/__init__.py': LIB_INIT,
        'src/idioms_lib/names.py': LIB_NAMES,
        'src/idioms_lib/Relay.py': LIB_RELAY,
        'scripts/star_package': STAR_PACKAGE,
        'scripts/star_rospy': STAR_ROSPY,
        'scripts/markers_ros1': MARKERS_ROS1,
        'scripts/markers_ros2': MARKERS_ROS2,
        'src/idioms_lib/endpoints.py': LIB_ENDPOINTS,
        'scripts/watch_a': WATCH_A,
        'scripts/watch_b': WATCH_B,
        'scripts/watch_c': WATCH_C,
        'scripts/monitors': MONITORS,
        'scripts/lambda_helper': LAMBDA_HELPER,
        'src/cycle_lib/__init__.py': CYCLE_INIT,
        'src/cycle_lib/core.py': CYCLE_CORE,
        'src/cycle_lib/tools.py': CYCLE_TOOLS,
        'scripts/cycle': CYCLE,
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
        name='idioms', path=str(package),
        build_base=str(tmp_path_factory.mktemp('build')))


def _node(summary, executable):
    return next(n for n in summary.nodes if n.executable == executable)


def _publishers(summary, executable):
    return sorted(
        (p.topic, p.msg_type, p.api, p.label, p.pattern, p.location,
         sorted(e.location for e in p.evidence if e.kind == 'publish_site'))
        for p in _node(summary, executable).publishers)


def test_ros1_updater_publishes_where_update_is_called(summary):
    assert _publishers(summary, 'diag_loop') == [
        ('/diagnostics', 'diagnostic_msgs::DiagnosticArray',
         'diagnostic_updater.Updater', 'independent', 'rate_loop',
         'scripts/diag_loop:14', ['scripts/diag_loop:23']),
        # published through the DiagnosedPublisher wrapping it
        ('chatter', 'std_msgs::String', 'rospy.Publisher', 'independent',
         'rate_loop', 'scripts/diag_loop:16', ['scripts/diag_loop:22']),
    ]
    # the ROS 1 updater has no timer of its own
    assert _node(summary, 'diag_loop').timers == []


def test_ros1_updater_forced_from_a_callback_is_dependent(summary):
    assert _publishers(summary, 'diag_callback') == [
        ('/diagnostics', 'diagnostic_msgs::DiagnosticArray',
         'diagnostic_updater.Updater', 'dependent', 'none',
         'scripts/diag_callback:9', ['scripts/diag_callback:13'])]


def test_ros2_updater_publishes_from_its_own_timer(summary):
    node = _node(summary, 'diag_ros2')
    assert sorted((t.api, t.callback, t.period, t.rate_hz, t.location)
                  for t in node.timers) == [
        ('diagnostic_updater.Updater', 'diagnostic_updater.Updater.update',
         '1.0', 1.0, 'scripts/diag_ros2:16'),
        ('diagnostic_updater.Updater', 'diagnostic_updater.Updater.update',
         'PERIOD', 4.0, 'scripts/diag_ros2:13')]
    assert _publishers(summary, 'diag_ros2') == [
        ('/diagnostics', 'diagnostic_msgs::DiagnosticArray',
         'diagnostic_updater.Updater', 'dependent', 'none',
         'scripts/diag_ros2:16',
         ['scripts/diag_ros2:16', 'scripts/diag_ros2:19']),
        ('/diagnostics', 'diagnostic_msgs::DiagnosticArray',
         'diagnostic_updater.Updater', 'independent', 'timer',
         'scripts/diag_ros2:13', ['scripts/diag_ros2:13']),
    ]


def test_diagnostics_connect_in_the_graph(summary):
    graph = graph_to_json(load_system([summary]))
    topic = next(t for t in graph['topics'] if t['name'] == '/diagnostics')
    assert sorted(topic['publishers']) == [
        'idioms/diag_callback', 'idioms/diag_loop', 'idioms/diag_ros2']


def test_names_a_package_re_exports_with_star_imports(summary):
    assert _publishers(summary, 'star_package') == [
        ('relay_out', 'std_msgs::String', 'rospy.Publisher', 'dependent',
         'none', 'src/idioms_lib/Relay.py:7', ['src/idioms_lib/Relay.py:10'])]
    node = _node(summary, 'star_package')
    assert [(s.topic, s.topic_is_literal, s.callback)
            for s in node.subscribers] == [
        ('relay_in', True, 'Relay.forward')]


def test_an_api_through_a_star_import(summary):
    assert _publishers(summary, 'star_rospy') == [
        ('paced', 'std_msgs::String', 'rospy.Publisher', 'independent',
         'rate_loop', 'scripts/star_rospy:8', ['scripts/star_rospy:11'])]
    node = _node(summary, 'star_rospy')
    assert [(s.topic, s.api) for s in node.subscribers] == [
        ('ticks', 'rospy.Subscriber')]
    assert node.name == 'star_rospy'


def _subscribers(summary, executable):
    return sorted((s.topic, s.msg_type, s.api, s.callback, s.location)
                  for s in _node(summary, executable).subscribers)


def _roots(summary, executable, kind):
    return sorted(r.function for r in _node(summary, executable).roots
                  if r.kind == kind)


def test_ros1_interactive_marker_feedback_is_an_input(summary):
    assert _subscribers(summary, 'markers_ros1') == [
        ('marker_server/feedback',
         'visualization_msgs::InteractiveMarkerFeedback',
         'interactive_markers.InteractiveMarkerServer', 'on_feedback',
         'scripts/markers_ros1:19')]
    assert _roots(summary, 'markers_ros1', 'subscriber') == [
        'on_feedback', 'on_menu']
    assert _publishers(summary, 'markers_ros1') == [
        ('cmd_vel', 'geometry_msgs::Twist', 'rospy.Publisher', 'dependent',
         'none', 'scripts/markers_ros1:20', ['scripts/markers_ros1:14'])]


def test_ros2_interactive_marker_server(summary):
    assert _subscribers(summary, 'markers_ros2') == [
        ('goal_marker/feedback',
         'visualization_msgs::InteractiveMarkerFeedback',
         'interactive_markers.InteractiveMarkerServer',
         'GoalMarker.on_feedback', 'scripts/markers_ros2:16')]
    assert _roots(summary, 'markers_ros2', 'subscriber') == [
        'GoalMarker.on_feedback', 'GoalMarker.on_other']
    assert _publishers(summary, 'markers_ros2') == [
        ('cmd_vel', 'geometry_msgs::Twist',
         'rclpy.node.Node.create_publisher', 'independent', 'timer',
         'scripts/markers_ros2:15', ['scripts/markers_ros2:29'])]
    graph = graph_to_json(load_system([summary]))
    node = next(n for n in graph['nodes'] if n['name'] == '/goal_marker_node')
    assert [t['resolved'] for t in node['subscribers']] == [
        '/goal_marker/feedback']


def test_helpers_make_one_endpoint_per_call_named_by_its_arguments(summary):
    # a module constant, a keyword argument and a default name the topics
    assert _subscribers(summary, 'watch_a') == [
        ('/arm/state', 'std_msgs::String', 'rospy.Subscriber',
         'StateWatch.on_state', 'src/idioms_lib/endpoints.py:12'),
        ('/base/mode', 'std_msgs::String', 'rospy.Subscriber',
         'StateWatch.on_state', 'src/idioms_lib/endpoints.py:12')]
    assert [(p.topic, p.topic_is_literal, p.location)
            for p in _node(summary, 'watch_a').publishers] == [
        ('watch_a/status', True, 'src/idioms_lib/endpoints.py:19')]
    # another node's calls are its own
    assert _subscribers(summary, 'watch_b') == [
        ('/lift/state', 'std_msgs::String', 'rospy.Subscriber',
         'StateWatch.on_state', 'src/idioms_lib/endpoints.py:12')]
    graph = graph_to_json(load_system([summary]))
    node = next(n for n in graph['nodes'] if n['name'] == '/watch_a')
    assert [t['resolved'] for t in node['publishers']] == ['/watch_a/status']
    # a call whose argument is not known: the helper's endpoint stays,
    # unnamed
    assert [(s.topic, s.topic_is_literal)
            for s in _node(summary, 'watch_c').subscribers] == [
        ('self.topic', False)]


def test_helper_objects_given_the_node(summary):
    assert _subscribers(summary, 'monitors') == [
        ('/api/ready', 'std_msgs::Bool', 'rclpy.node.Node.create_subscription',
         'TopicMonitor.callback', 'scripts/monitors:10'),
        ('/api/state', 'std_msgs::String',
         'rclpy.node.Node.create_subscription', 'TopicMonitor.callback',
         'scripts/monitors:10')]


def test_a_lambda_helper(summary):
    # a lambda's body is an expression, not statements
    assert summary.diagnostics == []
    assert [(p.topic, p.topic_is_literal, p.location)
            for p in _node(summary, 'lambda_helper').publishers] == [
        ('made_by_lambda', True, 'scripts/lambda_helper:5')]


def test_a_name_star_imports_lead_back_to(summary):
    assert not [d for d in summary.diagnostics if 'cycle' in d]
    assert [(p.topic, p.location)
            for p in _node(summary, 'cycle').publishers] == [
        ('core_out', 'src/cycle_lib/core.py:7')]
