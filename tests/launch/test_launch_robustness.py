# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Launch front ends: hostile, broken and huge launch files; one arithmetic."""

import time

from colcon_rsia.launch import file_kind
from colcon_rsia.launch import LaunchError
from colcon_rsia.launch import LaunchResult
from colcon_rsia.launch.common import MAX_INCLUDE_DEPTH
from launch_helpers import instances
from launch_helpers import load
from launch_helpers import one_sentence
from launch_helpers import write
import pytest


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
