# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The same code in C++ and in Python gives the same labels and names.

Each pattern is written twice, as a roscpp node and as a rospy node of one
catkin package, which is analysed unbuilt (model headers): both front ends
must label the publisher of ``out`` alike and resolve topic names alike,
as written here by hand.
"""

from colcon_rsia.package.runner import analyze
from colcon_rsia.render.graph import graph_to_json
from colcon_rsia.system.load import load_system
import pytest

# every node subscribes to `in` (so it has an input) and publishes `out`
# through publishOne (a function only the pattern calls: a function nobody
# calls would be a root of its own)
CPP = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <functional>
#include <stdexcept>
#include <thread>

void onIn(const std_msgs::String::ConstPtr&) {{}}
ros::Publisher pub;
void publishOne() {{ pub.publish(std_msgs::String()); }}

int main(int argc, char** argv) {{
  ros::init(argc, argv, "{name}");
  ros::NodeHandle nh;
  ros::Subscriber sub = nh.subscribe("in", 1, onIn);
  pub = nh.advertise<std_msgs::String>("out", 1);
  ros::Rate rate(10);
  bool busy = argc > 5;
  int n = 0;
{body}
  return 0;
}}
"""

PY = """#!/usr/bin/env python3
import functools
import threading

import rospy
from std_msgs.msg import String

pub = None


def on_in(msg):
    pass


def publish_one():
    pub.publish(String())


def main():
    global pub
    rospy.init_node('{name}')
    rospy.Subscriber('in', String, on_in)
    pub = rospy.Publisher('out', String, queue_size=1)
    rate = rospy.Rate(10)
    busy = len(rospy.myargv()) > 5
    n = 0
{body}


if __name__ == '__main__':
    main()
"""

INDEPENDENT_RATE_LOOP = ('independent', 'rate_loop')
INDEPENDENT_TIMER = ('independent', 'timer')
DEPENDENT = ('dependent', 'none')

# name: (C++ body of main, Python body of main, expected (label, pattern))
PATTERNS = {
    'rate_loop': ("""
  while (ros::ok()) {
    publishOne();
    rate.sleep();
  }""", """
    while not rospy.is_shutdown():
        publish_one()
        rate.sleep()""", INDEPENDENT_RATE_LOOP),
    'timer': ("""
  ros::Timer timer = nh.createTimer(
      ros::Duration(0.1), [](const ros::TimerEvent&) { publishOne(); });
  ros::spin();""", """
    rospy.Timer(rospy.Duration(0.1), lambda event: publish_one())
    rospy.spin()""", INDEPENDENT_TIMER),
    'continue_before_sleep': ("""
  while (ros::ok()) {
    publishOne();
    if (++n % 2) {
      continue;
    }
    rate.sleep();
  }""", """
    while not rospy.is_shutdown():
        publish_one()
        n += 1
        if n % 2:
            continue
        rate.sleep()""", DEPENDENT),
    'continue_after_sleep': ("""
  while (ros::ok()) {
    publishOne();
    rate.sleep();
    if (++n % 2) {
      continue;
    }
  }""", """
    while not rospy.is_shutdown():
        publish_one()
        rate.sleep()
        n += 1
        if n % 2:
            continue""", INDEPENDENT_RATE_LOOP),
    'sleep_behind_or': ("""
  while (ros::ok()) {
    publishOne();
    bool slept = busy || rate.sleep();
    (void)slept;
  }""", """
    while not rospy.is_shutdown():
        publish_one()
        slept = busy or rate.sleep()""", DEPENDENT),
    'sleep_behind_and': ("""
  while (ros::ok()) {
    publishOne();
    bool slept = busy && rate.sleep();
    (void)slept;
  }""", """
    while not rospy.is_shutdown():
        publish_one()
        slept = busy and rate.sleep()""", DEPENDENT),
    'sleep_in_catch': ("""
  while (ros::ok()) {
    try {
      publishOne();
    } catch (const std::exception&) {
      rate.sleep();
    }
  }""", """
    while not rospy.is_shutdown():
        try:
            publish_one()
        except Exception:
            rate.sleep()""", DEPENDENT),
    'sleep_in_try': ("""
  while (ros::ok()) {
    try {
      publishOne();
      rate.sleep();
    } catch (const std::exception&) {
      n = 0;
    }
  }""", """
    while not rospy.is_shutdown():
        try:
            publish_one()
            rate.sleep()
        except Exception:
            n = 0""", INDEPENDENT_RATE_LOOP),
    'sleep_in_branch': ("""
  while (ros::ok()) {
    publishOne();
    if (busy) {
      rate.sleep();
    }
  }""", """
    while not rospy.is_shutdown():
        publish_one()
        if busy:
            rate.sleep()""", DEPENDENT),
    'nested_loops': ("""
  while (ros::ok()) {
    for (int i = 0; i < 3; ++i) {
      publishOne();
    }
    rate.sleep();
  }""", """
    while not rospy.is_shutdown():
        for i in range(3):
            publish_one()
        rate.sleep()""", INDEPENDENT_RATE_LOOP),
    'sleep_in_inner_loop': ("""
  while (ros::ok()) {
    publishOne();
    for (int i = 0; i < 3; ++i) {
      rate.sleep();
    }
  }""", """
    while not rospy.is_shutdown():
        publish_one()
        for i in range(3):
            rate.sleep()""", DEPENDENT),
    'inner_continue_before_sleep': ("""
  while (ros::ok()) {
    for (int i = 0; i < 3; ++i) {
      if (i == n) {
        continue;
      }
      publishOne();
    }
    rate.sleep();
  }""", """
    while not rospy.is_shutdown():
        for i in range(3):
            if i == n:
                continue
            publish_one()
        rate.sleep()""", INDEPENDENT_RATE_LOOP),
    'rate_loop_in_a_thread': ("""
  std::thread worker([&rate]() {
    while (ros::ok()) {
      publishOne();
      rate.sleep();
    }
  });
  ros::spin();
  worker.join();""", """
    def loop():
        while not rospy.is_shutdown():
            publish_one()
            rate.sleep()

    worker = threading.Thread(target=loop)
    worker.start()
    rospy.spin()
    worker.join()""", INDEPENDENT_RATE_LOOP),
    'timer_callback_through_bind': ("""
  ros::Timer timer = nh.createTimer(ros::Duration(0.1), std::bind(&publishOne));
  ros::spin();""", """
    def tick(count, event):
        publish_one()

    rospy.Timer(rospy.Duration(0.1), functools.partial(tick, 1))
    rospy.spin()""", INDEPENDENT_TIMER),
    'publish_in_callback': ("""
  ros::Subscriber relay = nh.subscribe<std_msgs::String>(
      "relay_in", 1, [](const std_msgs::String::ConstPtr&) { publishOne(); });
  ros::spin();""", """
    rospy.Subscriber('relay_in', String, lambda msg: publish_one())
    rospy.spin()""", DEPENDENT),
}


# name: (C++ body, Python body, the name `named` publishes, resolved, when
# the node runs in the root namespace without a launch file)
NAME_PATTERNS = {
    'name_from_private_parameter': ("""
  ros::NodeHandle pnh("~");
  std::string topic;
  pnh.param<std::string>("topic", topic, "chatter");
  ros::Publisher named = nh.advertise<std_msgs::String>(topic, 1);
  ros::spin();""", """
    named = rospy.Publisher(
        rospy.get_param('~topic', 'chatter'), String, queue_size=1)
    rospy.spin()""", '/chatter'),
    'name_from_a_variable_set_once': ("""
  std::string topic = "scan";
  ros::Publisher named = nh.advertise<std_msgs::String>(topic, 1);
  ros::spin();""", """
    topic = 'scan'
    named = rospy.Publisher(topic, String, queue_size=1)
    rospy.spin()""", '/scan'),
    'name_set_twice_is_not_known': ("""
  std::string topic = "scan";
  if (busy) {
    topic = "other";
  }
  ros::Publisher named = nh.advertise<std_msgs::String>(topic, 1);
  ros::spin();""", """
    topic = 'scan'
    if busy:
        topic = 'other'
    named = rospy.Publisher(topic, String, queue_size=1)
    rospy.spin()""", None),
}


@pytest.fixture(scope='module')
def summary(tmp_path_factory):
    """The summary of the package holding every pattern in both languages."""
    root = tmp_path_factory.mktemp('parity')
    package = root / 'src' / 'parity'
    (package / 'src').mkdir(parents=True)
    (package / 'scripts').mkdir()
    (package / 'package.xml').write_text(
        '<?xml version="1.0"?>\n<package format="2">\n'
        '  <name>parity</name>\n  <version>0.0.1</version>\n'
        '  <description>test</description>\n'
        '  <maintainer email="a@b.c">a</maintainer>\n'
        '  <license>BSD</license>\n'
        '  <buildtool_depend>catkin</buildtool_depend>\n'
        '  <depend>roscpp</depend>\n  <depend>rospy</depend>\n'
        '  <depend>std_msgs</depend>\n</package>\n')
    cmake = ['cmake_minimum_required(VERSION 3.10)', 'project(parity)',
             'find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)',
             'catkin_package()',
             'include_directories(${catkin_INCLUDE_DIRS})']
    patterns = dict(PATTERNS, **NAME_PATTERNS)
    for name, (cpp_body, py_body, _) in patterns.items():
        (package / 'src' / f'{name}.cpp').write_text(
            CPP.format(name=name, body=cpp_body.strip('\n')))
        script = package / 'scripts' / f'py_{name}'
        script.write_text(PY.format(name=f'py_{name}',
                                    body=py_body.strip('\n')))
        script.chmod(0o755)
        cmake.append(f'add_executable({name} src/{name}.cpp)')
    cmake.append('catkin_install_python(PROGRAMS ' + ' '.join(
        f'scripts/py_{name}' for name in patterns) +
        ' DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})')
    (package / 'CMakeLists.txt').write_text('\n'.join(cmake) + '\n')
    outcome = analyze(
        name='parity', package_type='ros.catkin', path=str(package),
        build_base=str(root / 'build' / 'parity'), header_mode='model',
        workspace_package_dirs=[str(package)], without_build=True)
    assert outcome.summary is not None, outcome.error
    return outcome.summary


def _split(executable):
    if executable.startswith('py_'):
        return 'python', executable[3:]
    return 'cpp', executable


@pytest.fixture(scope='module')
def labels(summary):
    """{(language, pattern): (label, pattern)} of the `out` publishers."""
    found = {}
    for node in summary.nodes:
        language, name = _split(node.executable)
        for publisher in node.publishers:
            if publisher.topic == 'out':
                found[(language, name)] = (publisher.label, publisher.pattern)
    return found


@pytest.mark.parametrize('name', sorted(PATTERNS))
def test_cpp_and_python_label_alike(labels, name):
    expected = PATTERNS[name][2]
    assert labels.get(('cpp', name)) == expected
    assert labels.get(('python', name)) == expected


@pytest.fixture(scope='module')
def resolved_names(summary):
    """{(language, pattern): resolved name of `named`} in the graph."""
    found = {}
    for node in graph_to_json(load_system([summary]))['nodes']:
        language, name = _split(node['executable'])
        for publisher in node['publishers']:
            if publisher['topic'] != 'out':
                found[(language, name)] = publisher['resolved']
    return found


@pytest.mark.parametrize('name', sorted(NAME_PATTERNS))
def test_cpp_and_python_resolve_names_alike(resolved_names, name):
    expected = NAME_PATTERNS[name][2]
    assert resolved_names.get(('cpp', name), 'missing') == expected
    assert resolved_names.get(('python', name), 'missing') == expected
