# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The launch readers find an element's handler in a table by its tag."""

from pathlib import Path
import textwrap

from colcon_rsia.launch import load_launch
from colcon_rsia.launch.handlers import HandlerTable
import pytest


def write(directory, name, text):
    path = Path(directory) / name
    path.write_text(textwrap.dedent(text).lstrip())
    return path


def by_name(result):
    return {i.name: i for i in result.instances}


def test_a_key_with_two_handlers_is_refused():
    table = HandlerTable('element')

    @table.handles('node', 'lifecycle_node')
    def first():
        pass

    assert table.get('node') is first
    assert table.get('lifecycle_node') is first
    assert table.get('timer') is None
    assert 'node' in table and 'timer' not in table
    assert table.keys() == ['node', 'lifecycle_node']

    def second():
        pass

    with pytest.raises(ValueError) as error:
        table.handles('group', 'lifecycle_node')(second)
    assert str(error.value) == (
        "element 'lifecycle_node' has two handlers: first and second")
    assert 'group' not in table  # (a refused handler registers nothing)

    types = HandlerTable('action type')
    types.handles(int)(first)
    with pytest.raises(ValueError, match='^action type int has two'):
        types.handles(int)(second)


def test_ros1_elements_without_effect_pass_unknown_ones_are_noted(tmp_path):
    top = write(tmp_path, 'top.launch', """
        <launch>
          <machine name="m" address="localhost"/>
          <env name="A" value="1"/>
          <master auto="start"/>
          <test test-name="t" pkg="p" type="t"/>
          <bogus/>
          <group ns="g">
            <unheard_of/>
            <node pkg="p" type="talker" name="talker"/>
          </group>
        </launch>""")
    result = load_launch(top, environ={})
    assert [(i.namespace, i.name, i.executable)
            for i in result.instances] == [('/g', 'talker', 'talker')]
    assert result.unresolved == [
        f'{top}:6: unknown element <bogus> ignored',
        f'{top}:8: unknown element <unheard_of> ignored']


def test_ros2_xml_both_spellings_of_a_tag_are_read(tmp_path):
    top = write(tmp_path, 'top.launch.xml', """
        <launch>
          <log message="hello"/>
          <set-remap from="a" to="b"/>
          <set_remap from="c" to="d"/>
          <set-parameter name="x" value="1"/>
          <set_parameter name="y" value="2"/>
          <push-ros-namespace namespace="one"/>
          <node pkg="p" exec="first" name="first"/>
          <push_ros_namespace namespace="two"/>
          <timer period="1.0">
            <lifecycle_node pkg="p" exec="later" name="later"/>
          </timer>
          <wobble/>
        </launch>""")
    result = load_launch(top, environ={})
    found = by_name(result)
    assert sorted(found) == ['first', 'later']
    first = found['first']
    assert first.namespace == '/one'
    assert first.remaps == [('a', 'b'), ('c', 'd')]
    assert first.params == {'x': 1, 'y': 2}
    later = found['later']
    # (a lifecycle node is a node instance like any other)
    assert (later.namespace, later.kind) == ('/one/two', 'node')
    assert later.remaps == [('a', 'b'), ('c', 'd')]
    assert result.unresolved == [
        f'{top}:13: unknown element <wobble> ignored']
