# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""One arithmetic for the Python the analysis reads: launch files and nodes.

Expectations written by hand: Python's own results, and the limits of
colcon_rsia.python_arithmetic.
"""

import ast

from colcon_rsia import python_arithmetic
from colcon_rsia.launch import load_launch
from colcon_rsia.package.python_analysis import analyze_python_package
import pytest

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>arith</name>
  <version>0.0.1</version>
  <description>test</description>
  <maintainer email="a@b.c">a</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""

# rates written as arithmetic: 2 ** 3 is 8 Hz; 10 ** 400 is refused
RATES = """#!/usr/bin/env python3
import rospy
from std_msgs.msg import Empty

rospy.init_node('arith')
fast = rospy.Publisher('fast', Empty, queue_size=1)
huge = rospy.Publisher('huge', Empty, queue_size=1)


def on_fast(event):
    fast.publish(Empty())


def on_huge(event):
    huge.publish(Empty())


rospy.Timer(rospy.Duration(1.0 / 2 ** 3), on_fast)
rospy.Timer(rospy.Duration(1.0 / 10 ** 400), on_huge)
rospy.spin()
"""


@pytest.mark.parametrize('text, expected', [
    ('7 // 2', 3), ('2 ** 100', 2 ** 100), ("'ab' * 3", 'ababab'),
    ('7 % 3', 1), ('1 / 4', 0.25)])
def test_operations_are_pythons(text, expected):
    node = ast.parse(text, mode='eval').body
    left = ast.literal_eval(node.left)
    right = ast.literal_eval(node.right)
    assert python_arithmetic.binary(node.op, left, right) == expected


@pytest.mark.parametrize('text', [
    '10 ** 400', "'x' * 1000000000", '1 / 0', "'%s' % 1", '1 << 2'])
def test_what_would_be_huge_or_fails_is_refused(text):
    node = ast.parse(text, mode='eval').body
    left = ast.literal_eval(node.left)
    right = ast.literal_eval(node.right)
    with pytest.raises(python_arithmetic.Refused):
        python_arithmetic.binary(node.op, left, right)


def test_launch_files_and_nodes_agree(tmp_path):
    # $(eval) of a launch file
    launch = tmp_path / 'a.launch'
    launch.write_text(
        '<launch><node pkg="arith" type="arith" name="n">'
        '<param name="fast" value="$(eval 2 ** 3)"/>'
        '</node></launch>')
    [instance] = load_launch(str(launch), environ={}).instances
    assert instance.params['fast'] == 8
    huge = tmp_path / 'b.launch'
    huge.write_text(
        '<launch><node pkg="arith" type="arith" name="n">'
        '<param name="huge" value="$(eval 10 ** 400)"/>'
        '</node></launch>')
    [instance] = load_launch(str(huge), environ={}).instances
    assert 'huge' not in instance.params
    assert instance.unresolved == [
        f'{huge}:1: parameter huge not known statically '
        '(the power is too large)']
    # the same arithmetic in a node's rates
    package = tmp_path / 'arith'
    (package / 'scripts').mkdir(parents=True)
    (package / 'package.xml').write_text(PACKAGE_XML)
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.10)\nproject(arith)\n'
        'find_package(catkin REQUIRED)\ncatkin_package()\n')
    script = package / 'scripts' / 'arith'
    script.write_text(RATES)
    script.chmod(0o755)
    summary = analyze_python_package(
        name='arith', path=str(package), build_base=str(tmp_path / 'b'))
    [node] = summary.nodes
    rates = {p.topic: p.rate_hz for p in node.publishers}
    assert rates == {'fast': 8.0, 'huge': None}
