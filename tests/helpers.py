# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Helpers the test files of several subdirectories share.

Packages made by hand (sources and a compile database, no build), bags
written at chosen rates, expected results, colcon runs.
"""

import json
from pathlib import Path

import yaml

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>{name}</name><version>0.0.1</version><description>d</description>
  <maintainer email="dev@example.com">m</maintainer><license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""
GOOD_NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("out", 1);
  ros::Rate rate(5);
  while (ros::ok()) { pub.publish(std_msgs::String()); rate.sleep(); }
}
"""
# the bags' clock starts here (ns)
START_NS = 1_700_000_000 * 10**9


def catkin_package(root, name, sources, *, database=True, command=None):
    """A package with its sources and a compile database naming them."""
    package = root / 'src' / name
    (package / 'src').mkdir(parents=True)
    (package / 'package.xml').write_text(PACKAGE_XML.format(name=name))
    (package / 'CMakeLists.txt').write_text(
        f'project({name})\n' + ''.join(
            f'add_executable({Path(s).stem} src/{s})\n' for s in sources))
    build = root / 'build' / name
    build.mkdir(parents=True)
    entries = []
    for file_name, content in sources.items():
        path = package / 'src' / file_name
        if isinstance(content, bytes):
            path.write_bytes(content)
        elif content is not None:
            path.write_text(content)
        entries.append({
            'directory': str(build), 'file': str(path),
            'command': (command or '/usr/bin/c++') +
            f' -std=c++17 -o x.o -c {path}'})
    if database:
        (build / 'compile_commands.json').write_text(json.dumps(entries))
    return package


def read_summary(root, name):
    """The summary.json the analysis wrote for package `name`."""
    path = root / 'build' / name / 'rsia' / 'summary.json'
    return json.loads(path.read_text())


def write_bag(path, topics, storage='ros1', seconds=4.0):
    """A bag with `topics` {name: Hz} of std_msgs/String messages.

    :param storage: 'ros1', 'sqlite3' or 'mcap'
    """
    from rosbags.typesys import get_typestore
    from rosbags.typesys import Stores
    if storage == 'ros1':
        from rosbags.rosbag1 import Writer
        typestore = get_typestore(Stores.ROS1_NOETIC)
        writer = Writer(path)
        serialize = typestore.serialize_ros1
    else:
        from rosbags.rosbag2 import StoragePlugin
        from rosbags.rosbag2 import Writer
        typestore = get_typestore(Stores.ROS2_HUMBLE)
        writer = Writer(path, version=9, storage_plugin={
            'sqlite3': StoragePlugin.SQLITE3,
            'mcap': StoragePlugin.MCAP}[storage])
        serialize = typestore.serialize_cdr
    msgtype = 'std_msgs/msg/String'
    data = serialize(typestore.types[msgtype](data='x'), msgtype)
    messages = []
    with writer:
        for topic, hz in sorted(topics.items()):
            connection = writer.add_connection(
                topic, msgtype, typestore=typestore)
            # the topic starts late: its rate is measured over its own span
            first = START_NS + 10**9
            count = int(seconds * hz) + 1
            messages += [(first + round(i * 1e9 / hz), connection)
                         for i in range(count)]
        for timestamp, connection in sorted(messages, key=lambda m: m[0]):
            writer.write(connection, timestamp, data)
    return path


def read_yaml(path):
    """The content of a YAML file (an expected result written by hand)."""
    with open(path) as h:
        return yaml.safe_load(h)


def assert_no_traceback(result):
    """A completed colcon run printed no Python traceback."""
    assert 'Traceback' not in result.stdout + result.stderr, \
        result.stdout[-3000:] + result.stderr[-3000:]


def colcon_json(workspace, *args):
    """The JSON a `colcon rsia` query prints on the workspace's sources."""
    result = workspace.colcon(
        'rsia', *args, '--base-paths', str(workspace.src),
        '--format', 'json', check=True)
    return json.loads(result.stdout)
