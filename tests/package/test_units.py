# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Small pure functions: arguments, constants, message types, storage."""

import json
import os
from types import SimpleNamespace
from unittest import mock

from colcon_core.command import CommandContext
from colcon_core.event.job import JobEnded
from colcon_core.event_reactor import EventReactorShutdown
from colcon_rsia.event_handler.rsia import RsiaEventHandler
from colcon_rsia.frontend.compile_db import clang_arguments
from colcon_rsia.frontend.compile_db import CompileDatabaseError
from colcon_rsia.frontend.compile_db import load_compile_database
from colcon_rsia.frontend.cpp import normalize_msg_type
from colcon_rsia.frontend.cpp.const_eval import evaluate_tokens
from colcon_rsia.package.runner import analyze
from colcon_rsia.package.runner import missing_compile_db_message
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.store import read_summary
from colcon_rsia.summary.store import SummaryError
from colcon_rsia.summary.store import write_summary
import pytest


def test_clang_arguments_drop_compiler_output_and_dependency_files():
    argv = ['/usr/bin/c++', '-DX=1', '-I/inc', '-MD', '-MT', 'a.o', '-MF',
            'a.d', '-o', 'a.o', '-c', '/src/a.cpp', '-std=gnu++17']
    assert clang_arguments(argv, '/src/a.cpp', '/build') == \
        ['-DX=1', '-I/inc', '-std=gnu++17']


def test_compile_database_errors_are_one_sentence(tmp_path):
    with pytest.raises(CompileDatabaseError, match='no compile database'):
        load_compile_database(str(tmp_path / 'missing.json'))
    broken = tmp_path / 'compile_commands.json'
    broken.write_text('[{"directory": ')
    with pytest.raises(CompileDatabaseError, match='unreadable'):
        load_compile_database(str(broken))


def test_compile_database_reads_command_and_arguments_forms(tmp_path):
    db = tmp_path / 'compile_commands.json'
    db.write_text(json.dumps([
        {'directory': '/b', 'file': '/s/a.cpp',
         'command': 'c++ -I"/with space" -c /s/a.cpp -o a.o'},
        {'directory': '/b', 'file': 'rel.cpp',
         'arguments': ['c++', '-DY', '-c', 'rel.cpp']},
        {'file': 'no-directory.cpp'},
    ]))
    entries = {e.file: e.arguments for e in load_compile_database(str(db))}
    assert entries == {'/s/a.cpp': ['-I/with space'], '/b/rel.cpp': ['-DY']}


def test_constant_expressions_from_macro_tokens():
    macros = {'HZ': ['20'], 'PERIOD': ['(', '1.0', '/', 'HZ', ')']}
    assert evaluate_tokens(['HZ'], macros) == 20.0
    assert evaluate_tokens(['PERIOD'], macros) == pytest.approx(0.05)
    assert evaluate_tokens(['2', '*', '(', '3', '+', '4', ')']) == 14.0
    assert evaluate_tokens(['-', '0x10']) == -16.0
    assert evaluate_tokens(['rate_param']) is None
    assert evaluate_tokens(['1', '/', '0']) is None
    assert evaluate_tokens(['(', '1']) is None


@pytest.mark.parametrize('spelling, expected', [
    ('const std_msgs::String::ConstPtr &', 'std_msgs::String'),
    ('const sensor_msgs::Image_<std::allocator<void> > &',
     'sensor_msgs::Image'),
    ('boost::shared_ptr<const geometry_msgs::Twist>', 'geometry_msgs::Twist'),
    ('const ros::MessageEvent<const std_msgs::Int32> &', 'std_msgs::Int32'),
    ('std_msgs::Float64', 'std_msgs::Float64'),
    ('', None),
])
def test_message_types_are_normalised(spelling, expected):
    assert normalize_msg_type(spelling) == expected


def _summary():
    return PackageSummary(
        package='p', path='/p', tool_version='0', nodes=[Node(
            id='p/n', package='p', executable='n', kind='executable')])


def test_summary_round_trip_and_atomic_write(tmp_path):
    path = write_summary(str(tmp_path), _summary())
    assert read_summary(path) == _summary()
    assert os.listdir(os.path.dirname(path)) == ['summary.json']


@pytest.mark.parametrize('content, message', [
    ('{"schema": "colcon-rsia/summary@1", "nodes": [', 'corrupted summary'),
    ('{"schema": "colcon-rsia/summary@99", "nodes": []}',
     "unsupported summary schema 'colcon-rsia/summary@99'"),
    ('{"schema": "colcon-rsia/summary@1", "nodes": [{"id": 1}]}',
     'malformed summary'),
    ('[]', 'not an object'),
])
def test_unusable_summaries_are_one_clear_message(tmp_path, content,
                                                  message):
    path = tmp_path / 'summary.json'
    path.write_text(content)
    with pytest.raises(SummaryError) as info:
        read_summary(str(path))
    assert message in str(info.value)
    assert str(path) in str(info.value)


def test_missing_compile_database_message_tells_how_to_get_one():
    message = missing_compile_db_message(['-DCMAKE_BUILD_TYPE=Release'])
    assert '-DCMAKE_EXPORT_COMPILE_COMMANDS=ON' in message
    assert 'compile-commands' in message
    assert 'defaults.yaml' in message
    asked = missing_compile_db_message(['-DCMAKE_EXPORT_COMPILE_COMMANDS=ON'])
    assert 'generator' in asked


def test_runner_never_raises(tmp_path):
    (tmp_path / 'compile_commands.json').write_text('not json')
    outcome = analyze(name='p', package_type='ros.catkin',
                      path=str(tmp_path), build_base=str(tmp_path))
    assert outcome.summary is None
    assert 'unreadable compile database' in outcome.error
    with mock.patch('colcon_rsia.package.runner.analyze_package',
                    side_effect=KeyError('boom')):
        outcome = analyze(name='p', package_type='ros.catkin',
                          path=str(tmp_path), build_base=str(tmp_path))
    assert 'internal error' in outcome.error
    skipped = analyze(name='p', package_type='cargo',
                      path=str(tmp_path), build_base=str(tmp_path))
    assert skipped.skipped


def _job(tmp_path, name='pkg', package_type='ros.catkin', cmake_args=None):
    job = mock.Mock()
    job.task_context.pkg.name = name
    job.task_context.pkg.type = package_type
    job.task_context.pkg.path = str(tmp_path / 'src' / name)
    job.task_context.args.build_base = str(tmp_path / 'build' / name)
    job.task_context.args.cmake_args = cmake_args
    # colcon's TaskContext: the package's dependencies, by name
    job.task_context.dependencies = {}
    return job


def test_event_handler_is_disabled_by_default_and_acts_only_on_build(
        tmp_path, capsys):
    handler = RsiaEventHandler()
    assert handler.enabled is False
    handler.context = CommandContext(
        command_name='colcon', args=SimpleNamespace(verb_name='test'))
    handler((JobEnded('pkg', 0), _job(tmp_path)))
    handler((EventReactorShutdown(), None))
    assert capsys.readouterr().out == ''


def test_event_handler_warns_once_per_package_without_database(
        tmp_path, capsys):
    handler = RsiaEventHandler()
    handler.context = CommandContext(
        command_name='colcon', args=SimpleNamespace(verb_name='build'))
    handler((JobEnded('pkg', 0), _job(tmp_path)))
    handler((JobEnded('failed', 1), _job(tmp_path, name='failed')))
    handler((JobEnded('rs', 0), _job(tmp_path, name='rs',
                                     package_type='cargo')))
    handler((EventReactorShutdown(), None))
    out = capsys.readouterr().out
    assert out.count('rsia: pkg: no compile_commands.json') == 1
    assert '--cmake-args -DCMAKE_EXPORT_COMPILE_COMMANDS=ON' in out
    assert 'failed' not in out and 'rsia: rs' not in out
    assert 'rsia: analysed 0 of 1 packages' in out


@pytest.mark.skipif(not hasattr(os, 'setpriority'), reason='POSIX only')
def test_event_handler_analyzes_at_a_lower_priority_than_the_build(
        tmp_path):
    seen = {}

    def analyze(**kwargs):
        # runs in the handler's worker thread
        seen['worker'] = os.getpriority(os.PRIO_PROCESS, 0)
        return SimpleNamespace(skipped=True, summary=None)

    build_priority = os.getpriority(os.PRIO_PROCESS, 0)
    handler = RsiaEventHandler()
    handler.context = CommandContext(
        command_name='colcon', args=SimpleNamespace(verb_name='build'))
    with mock.patch('colcon_rsia.package.runner.analyze', analyze):
        handler((JobEnded('pkg', 0), _job(tmp_path)))
        handler((EventReactorShutdown(), None))
    assert seen['worker'] == min(19, build_priority + handler.NICENESS)
    # the build's own thread keeps its priority
    assert os.getpriority(os.PRIO_PROCESS, 0) == build_priority


def _catkin_script_package(root):
    """A catkin package whose one node is a Python script it installs."""
    package = root / 'talk_pkg'
    (package / 'scripts').mkdir(parents=True)
    (package / 'package.xml').write_text(
        '<package format="2"><name>talk_pkg</name><version>0.1.0</version>'
        '<description>d</description><maintainer email="m@e.org">m'
        '</maintainer><license>BSD</license>'
        '<buildtool_depend>catkin</buildtool_depend></package>')
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.0.2)\n'
        'project(talk_pkg)\n'
        'find_package(catkin REQUIRED COMPONENTS rospy)\n'
        'catkin_package()\n'
        'catkin_install_python(PROGRAMS scripts/talker.py\n'
        '  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n')
    (package / 'scripts' / 'talker.py').write_text(
        '#!/usr/bin/env python3\n'
        'import rospy\n'
        'from std_msgs.msg import String\n'
        '\n'
        'if __name__ == "__main__":\n'
        '    rospy.init_node("talker")\n'
        '    pub = rospy.Publisher("chatter", String, queue_size=1)\n'
        '    rate = rospy.Rate(10)\n'
        '    while not rospy.is_shutdown():\n'
        '        pub.publish(String(data="hi"))\n'
        '        rate.sleep()\n')
    return package


def test_each_package_type_has_its_analyzer(tmp_path):
    package = _catkin_script_package(tmp_path / 'src')
    build_base = tmp_path / 'build' / 'talk_pkg'
    build_base.mkdir(parents=True)

    def run(package_type):
        return analyze(name='talk_pkg', package_type=package_type,
                       path=str(package), build_base=str(build_base))

    # catkin: C++ and the scripts it installs; no C++ here, so the script
    # is analysed without a compile database
    catkin = run('ros.catkin')
    assert catkin.warning is None and catkin.error is None
    assert [(n.executable, [p.topic for p in n.publishers])
            for n in catkin.summary.nodes] == [('talker.py', ['chatter'])]
    # plain CMake: C++ only, which needs the compile database
    cmake = run('cmake')
    assert cmake.summary is None
    assert cmake.warning.startswith('no compile_commands.json; not analysed')
    # a type no analyser takes: skipped (said by `analyze`, not in a build)
    for package_type in ('python', 'cargo'):
        skipped = run(package_type)
        assert skipped.skipped and skipped.summary is None
        assert skipped.warning == (
            f"package type '{package_type}' is not analysed by this "
            'version; skipped')
