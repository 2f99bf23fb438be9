# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Property-based tests of the substitution parser and a bounded fuzz run.

Every run is derandomized: the same inputs on every machine.
"""

import os
from pathlib import Path
import re
import tempfile

from colcon_rsia.launch import LaunchError
from colcon_rsia.launch import LaunchResult
from colcon_rsia.launch import load_launch
from colcon_rsia.launch import NodeInstance
from colcon_rsia.launch.safe_eval import evaluate
from colcon_rsia.launch.substitutions import Resolver
from colcon_rsia.launch.substitutions import Unresolved
from hypothesis import given
from hypothesis import HealthCheck
from hypothesis import settings
from hypothesis import strategies as st
import pytest

FILES = Path(__file__).resolve().parent / 'launch_files'
# inputs per front end in the fuzz run
FUZZ_EXAMPLES = 2000
# every input is written to a file: a memory file system when there is one
# (some container /tmp file systems take milliseconds per write)
FUZZ_DIR = '/dev/shm' if os.access('/dev/shm', os.W_OK) else None

PROPERTY = settings(
    max_examples=300, derandomize=True, database=None, deadline=None,
    suppress_health_check=[HealthCheck.too_slow])
FUZZ = settings(
    max_examples=FUZZ_EXAMPLES, derandomize=True, database=None,
    deadline=None, suppress_health_check=list(HealthCheck))

NAMES = st.from_regex(r'[a-z_][a-z0-9_]{0,8}', fullmatch=True)
PLAIN = st.text(st.characters(blacklist_categories=('Cs',)), max_size=40) \
    .filter(lambda t: '$(' not in t)
SUBSTITUTION_ALPHABET = st.sampled_from(
    list('$()\'" \t\nabc_-/.*+=<>!,0123456789') +
    ['$(', 'arg ', 'var ', 'eval ', 'env ', 'optenv ', 'find ', 'anon ',
     'dirname', 'find-pkg-share ', "arg('a')", ' and ', ' or ', 'not ',
     ' if ', ' else ', '**', '9' * 20])
NOISY = st.lists(SUBSTITUTION_ALPHABET, max_size=40).map(''.join)


def resolver(dialect, args, notes=None):
    def lookup(name):
        if name not in args:
            raise Unresolved(f'unknown {name}')
        return args[name]

    def find(package, kind):
        if package == 'pkg':
            return '/ws/pkg'
        raise Unresolved(f'no {package}')

    return Resolver(dialect=dialect, lookup_arg=lookup,
                    environ={'HOME_X': '/home/x'}, find_package=find,
                    current_file='/ws/pkg/launch/a.launch',
                    notes=notes if notes is not None else [])


DIALECTS = st.sampled_from(['ros1', 'ros2'])


def arg_call(dialect, name):
    return f'$({"arg" if dialect == "ros1" else "var"} {name})'


@PROPERTY
@given(dialect=DIALECTS, text=PLAIN)
def test_text_without_substitutions_is_unchanged(dialect, text):
    assert resolver(dialect, {}).substitute(text) == text


@PROPERTY
@given(dialect=DIALECTS, name=NAMES, value=PLAIN, prefix=PLAIN,
       suffix=PLAIN)
def test_argument_is_replaced_in_place(dialect, name, value, prefix, suffix):
    text = prefix + arg_call(dialect, name) + suffix
    assert resolver(dialect, {name: value}).substitute(text) == \
        prefix + value + suffix


@PROPERTY
@given(dialect=DIALECTS, outer=NAMES, inner=NAMES, value=PLAIN)
def test_nested_arguments_resolve_inside_out(dialect, outer, inner, value):
    args = {outer: inner, inner: value}
    if outer == inner:
        args = {outer: outer}
        value = outer
    text = arg_call(dialect, arg_call(dialect, outer))
    assert resolver(dialect, args).substitute(text) == value


@PROPERTY
@given(a=st.integers(-10 ** 6, 10 ** 6), b=st.integers(-10 ** 6, 10 ** 6))
def test_eval_computes_over_arguments(a, b):
    args = {'a': str(a), 'b': str(b)}
    ros1 = resolver('ros1', args)
    assert ros1.substitute('$(eval a + b * 2)') == str(a + b * 2)
    assert ros1.substitute("$(eval arg('a') < b)") == str(a < b)
    ros2 = resolver('ros2', args)
    assert ros2.substitute('$(eval "$(var a) - $(var b)")') == str(a - b)


@PROPERTY
@given(dialect=DIALECTS, text=NOISY, args=st.dictionaries(NAMES, PLAIN,
                                                          max_size=3))
def test_substitution_only_resolves_or_says_why(dialect, text, args):
    notes = []
    try:
        value = resolver(dialect, args, notes).substitute(text)
    except Unresolved as e:
        assert str(e)
    else:
        assert isinstance(value, str)


@PROPERTY
@given(text=NOISY)
def test_safe_eval_only_evaluates_or_says_why(text):
    try:
        value = evaluate(text, lookup=lambda n: '1',
                         functions={'arg': lambda n: '1'})
    except Unresolved as e:
        assert str(e)
    else:
        assert isinstance(value, (str, int, float, bool, type(None)))


# the bounded fuzz run: mutated realistic files through each front end

ROS1_SEEDS = [
    (FILES / 'ros1_ws/sysbot_bringup/launch/system.launch').read_text(),
    (FILES / 'ros1_ws/sysbot_bringup/launch/drivers.launch').read_text(),
    (FILES / 'ros1_ws/sysbot_bringup/launch/perception.launch').read_text(),
    '<launch><arg name="a" default="$(arg a)"/>'
    '<include file="$(dirname)/fuzz.launch"/>'
    '<node pkg="p" type="t" name="$(eval arg(\'a\') + \'x\')"/></launch>',
    '<launch><rosparam>a: {b: [1, 2]}</rosparam><group ns="$(env X)">'
    '<param name="p" type="yaml" value="[1, {a: 2}]"/></group></launch>',
]
ROS2_XML_SEEDS = [
    (FILES / 'ros2_ws/robot_bringup/launch/sensors.launch.xml').read_text(),
    '<launch><arg name="a" default="1"/><let name="b" value="$(var a)2"/>'
    '<group scoped="false"><push-ros-namespace namespace="$(var b)"/>'
    '<set_remap from="x" to="y"/></group>'
    '<include file="$(dirname)/fuzz.launch.xml"><arg name="a" value="2"/>'
    '</include><node_container pkg="c" exec="c" name="c">'
    '<composable_node pkg="p" plugin="p::P" name="$(eval \'$(var a)\')"/>'
    '</node_container></launch>',
]
YAML_SEEDS = [
    (FILES / 'ros2_ws/robot_bringup/launch/navigation.launch.yaml')
    .read_text(),
    'launch:\n- include:\n    file: $(dirname)/fuzz.launch.yaml\n'
    '- node: {pkg: p, exec: e, param: [{from: $(dirname)/p.yaml}]}\n',
]
PYTHON_SEEDS = [
    (FILES / 'ros2_ws/robot_bringup/launch/robot.launch.py').read_text(),
    (FILES / 'ros2_ws/robot_bringup/launch/monitor.launch.py').read_text(),
    'from launch import LaunchDescription as L\n'
    'from launch_ros.actions import Node\n'
    'def f(n):\n    return f(n) if n else [Node(package=n)]\n'
    'def generate_launch_description():\n'
    '    x = []\n    for i in range(3):\n        x = x + x + [f(i)]\n'
    '    while True:\n        x.append(x)\n'
    '    return L(x + [{"a": 1}[0], "%s" % 1, f"{x}"])\n',
]
TOKENS = [
    '<', '>', '/>', '</launch>', '<group>', '</group>', '"', "'", '$(',
    ')', '$(arg a)', '$(var a)', '$(eval 1 +', '$(find pkg)', '&amp;',
    '&lol;', '<!DOCTYPE x [<!ENTITY lol "x">]>', '<include file="x"/>',
    '\n', ' ', ':', '- ', '- node:', '  ', '{', '}', '[', ']', '*a', '&a ',
    '!!python/object:os.system', 'def ', 'return ', 'for ', 'if ', '(', ',',
    'Node(', 'LaunchDescription([', ']))', 'import os\n', '\x00', '\ufffd',
    'ns="', 'name="', 'if="$(arg a)"', 'pass_all_args="true"', '9' * 50,
]
MUTATION = st.tuples(
    st.sampled_from(['insert', 'delete', 'replace', 'duplicate']),
    st.floats(0, 1), st.integers(1, 40),
    st.one_of(st.sampled_from(TOKENS), st.text(max_size=8)))


def mutate(seed, mutations):
    text = seed
    for kind, where, size, token in mutations:
        at = int(where * len(text))
        if kind == 'insert':
            text = text[:at] + token + text[at:]
        elif kind == 'delete':
            text = text[:at] + text[at + size:]
        elif kind == 'replace':
            text = text[:at] + token + text[at + size:]
        else:
            text = text[:at] + text[at:at + size] * 2 + text[at + size:]
    return text


# quoted values (XML attributes, Python strings) and YAML scalars: mutating
# only them keeps most inputs well-formed, so the front ends behind the
# parsers get exercised
_QUOTED = re.compile(r'"[^"\n<>&\\]*"|\'[^\'\n<>&\\]*\'')
_YAML_VALUE = re.compile(r'(?<=: )[^\n]+')
_UNSAFE = str.maketrans('', '', '"\'<>&\n\\\x00')


def mutate_values(seed, picks, yaml_style):
    text = seed
    for where, value in picks:
        pattern = _YAML_VALUE if yaml_style else _QUOTED
        spans = list(pattern.finditer(text))
        if not spans:
            break
        span = spans[int(where * (len(spans) - 1))]
        value = value.translate(_UNSAFE)
        replacement = f'"{value}"' if yaml_style else \
            span.group()[0] + value + span.group()[0]
        text = text[:span.start()] + replacement + text[span.end():]
    return text


VALUES = st.one_of(NOISY, st.sampled_from([
    '$(arg a)', '$(var a)', '$(eval 1 + 2)', '$(eval 10 ** 400)',
    '$(find pkg)/launch/fuzz.launch', '$(dirname)/fuzz.launch.xml',
    '$(anon x)', '$(optenv A b c)', '$(env X)', '/abs/ns', '~private', '',
    '$(find-pkg-share pkg)', '$(eval "\'$(var a)\' == \'1\'")', 'true',
    'false']))


def inputs(seeds, yaml_style=False):
    mutated = st.builds(mutate, st.sampled_from(seeds),
                        st.lists(MUTATION, max_size=6))
    values = st.builds(mutate_values, st.sampled_from(seeds),
                       st.lists(st.tuples(st.floats(0, 1), VALUES),
                                min_size=1, max_size=6),
                       st.just(yaml_style))
    spliced = st.builds(lambda a, b, x, y: a[:int(x * len(a))] +
                        b[int(y * len(b)):], st.sampled_from(seeds),
                        st.sampled_from(seeds), st.floats(0, 1),
                        st.floats(0, 1))
    return st.one_of(values, values, values, mutated, mutated, spliced,
                     st.text(max_size=200))


def check(result_or_error):
    if isinstance(result_or_error, LaunchError):
        message = str(result_or_error)
        assert 'internal error' not in message, message
        # every nesting has its own limit: the Python stack never overflows
        assert 'too deeply to analyse' not in message, message
        assert message.endswith('.')
        return
    result = result_or_error
    assert isinstance(result, LaunchResult)
    for instance in result.instances:
        assert isinstance(instance, NodeInstance)
        assert instance.namespace is None or \
            instance.namespace.startswith('/')
        assert all(isinstance(n, str) for n in instance.unresolved)
        assert all(isinstance(a, str) and isinstance(b, str)
                   for a, b in instance.remaps)
    assert all(isinstance(n, str) for n in result.unresolved)


@pytest.mark.parametrize('name,seeds', [
    ('fuzz.launch', ROS1_SEEDS),
    ('fuzz.launch.xml', ROS2_XML_SEEDS),
    ('fuzz.launch.yaml', YAML_SEEDS),
    ('fuzz.launch.py', PYTHON_SEEDS),
])
def test_fuzz_front_end(name, seeds, capsys):
    counts = {'inputs': 0, 'errors': 0}
    with tempfile.TemporaryDirectory(dir=FUZZ_DIR) as directory:
        path = Path(directory) / name
        (Path(directory) / 'p.yaml').write_text(
            '/**:\n  ros__parameters:\n    a: 1\n')

        @FUZZ
        @given(text=inputs(seeds, yaml_style=name.endswith('.yaml')))
        def run(text):
            counts['inputs'] += 1
            path.write_text(text, encoding='utf-8', errors='replace')
            try:
                result = load_launch(path, environ={},
                                     package_paths={'pkg': directory})
            except LaunchError as e:
                counts['errors'] += 1
                check(e)
            else:
                check(result)

        run()
    with capsys.disabled():
        print(f'\n{name}: {counts["inputs"]} fuzz inputs, '
              f'{counts["errors"]} refused with LaunchError, the rest read')
    assert counts['inputs'] >= FUZZ_EXAMPLES
