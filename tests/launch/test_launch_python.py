# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Launch front ends: ROS 2 Python launch files, read statically."""

from pathlib import Path

from colcon_rsia.launch import LaunchError
from launch_helpers import instances
from launch_helpers import load
from launch_helpers import ROS2_PKG
from launch_helpers import write
import pytest


# ROS 2 Python


def test_ros2_python_system():
    result = load(ROS2_PKG / 'launch' / 'robot.launch.py',
                  package_paths={'robot_bringup': ROS2_PKG})
    assert result.unresolved == []
    found = instances(result)
    assert sorted(found) == [
        '/monitor_0', '/monitor_1', '/robot1/camera_container',
        '/robot1/controller', '/robot1/front', '/robot1/gps',
        '/robot1/imu/imu', '/robot1/lidar', '/robot1/local/local_planner',
        '/robot1/planner', '/robot1/rear', '/robot1/vision/detector']
    controller = found['/robot1/controller']
    assert controller.remaps == [('/tf', 'tf'), ('cmd_vel', 'cmd_vel_safe'),
                                 ('odom', '/odom')]
    assert controller.params == {
        'rate': 50.0, 'base_frame': 'robot1/base_link', 'gains.p': 1.0,
        'gains.d': 0.1, 'use_sim_time': False, 'kp': 3.0}
    lidar = found['/robot1/lidar']
    # include arguments from a LaunchConfiguration and a literal
    assert lidar.params == {'rate': 15, 'frame_id': 'lidar_link',
                            'limits.min_range': 0.1,
                            'limits.max_range': 30}
    assert lidar.remaps == [('/tf', 'tf'), ('scan', 'scan_raw')]
    imu = found['/robot1/imu/imu']
    assert imu.remaps == [('/tf', 'tf'), ('data', 'data_raw')]
    assert imu.params == {'rate': 100}
    planner = found['/robot1/planner']
    assert planner.params == {'use_sim_time': False, 'expected_rate': 2.0,
                              'grid.resolution': 0.05, 'use_grid': True}
    front, rear = found['/robot1/front'], found['/robot1/rear']
    assert (front.kind, front.executable, front.params) == (
        'component', 'robot_camera::Driver', {'fps': 30})
    assert rear.params == {'fps': 15}
    assert found['/robot1/camera_container'].kind == 'container'
    assert found['/robot1/vision/detector'].kind == 'component'
    assert found['/monitor_1'].remaps == [('in', 'odom')]
    assert {Path(f).name for f in result.files} == {
        'robot.launch.py', 'sensors.launch.xml', 'nav_params.yaml',
        'navigation.launch.yaml', 'monitor.launch.py'}


def test_ros2_python_arguments_and_conditions():
    result = load(ROS2_PKG / 'launch' / 'robot.launch.py',
                  arguments={'robot': 'r2', 'nav': 'false',
                             'lidar_rate': '5'},
                  package_paths={'robot_bringup': ROS2_PKG})
    found = instances(result)
    assert '/r2/planner' not in found
    assert found['/r2/lidar'].params['rate'] == 5
    assert found['/r2/controller'].params['base_frame'] == 'r2/base_link'


PYTHON_LAUNCH = """
    import os

    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, OpaqueFunction
    from launch.conditions import LaunchConfigurationEquals, UnlessCondition
    from launch.substitutions import LaunchConfiguration, PythonExpression
    from launch_ros.actions import Node
    import my_helpers

    NAMESPACE = 'fleet'
    RATES = {'fast': 100, 'slow': 1}


    def make(name, **extra):
        return Node(package='pkg', executable='worker', name=name,
                    namespace=NAMESPACE, **extra)


    def generate_launch_description():
        ld = LaunchDescription()
        ld.add_action(DeclareLaunchArgument('mode', default_value='fast'))
        ld.add_action(make('known', parameters=[{'rate': RATES['fast']}]))
        if os.environ.get('FLEET_SIZE'):
            ld.add_action(make('maybe'))
        else:
            ld.add_action(make('otherwise'))
        for robot in my_helpers.robots():
            ld.add_action(make(robot))
        workers = [make(f'w{i}') for i in range(2)]
        ld.add_action(Node(package='pkg', executable=my_helpers.exe(),
                           name='unknown_exe'))
        ld.add_action(Node(
            package='pkg', executable='mode', name='fast_only',
            condition=LaunchConfigurationEquals('mode', 'fast')))
        ld.add_action(Node(
            package='pkg', executable='mode', name='not_fast',
            condition=UnlessCondition(PythonExpression(
                ["'", LaunchConfiguration('mode'), "' == 'fast'"]))))
        ld.add_action(OpaqueFunction(function=lambda context: []))
        for w in workers:
            ld.add_action(w)
        return ld
    """


def test_ros2_python_constructs(tmp_path):
    path = write(tmp_path, 'x.launch.py', PYTHON_LAUNCH)
    result = load(path, environ={'FLEET_SIZE': ''})
    names = [i.name for i in result.instances]
    assert names == ['known', 'otherwise', None, 'unknown_exe', 'fast_only',
                     'w0', 'w1']
    found = {i.name: i for i in result.instances}
    assert found['known'].params == {'rate': 100}
    assert found['known'].namespace == '/fleet'
    # a loop over a call not understood: one instance, name unknown
    looped = found[None]
    assert any('loop' in n for n in looped.unresolved)
    assert found['unknown_exe'].executable is None
    assert any('executable not known' in n
               for n in found['unknown_exe'].unresolved)
    notes = '\n'.join(result.unresolved)
    assert 'my_helpers.robots() not interpreted' in notes
    assert 'OpaqueFunction' in notes

    result = load(path, arguments={'mode': 'slow'}, environ={})
    names = [i.name for i in result.instances]
    assert 'fast_only' not in names and 'not_fast' in names


def test_ros2_python_unknown_condition_keeps_both_branches(tmp_path):
    path = write(tmp_path, 'x.launch.py', """
        from launch import LaunchDescription
        from launch_ros.actions import Node
        import socket


        def generate_launch_description():
            nodes = []
            if socket.gethostname() == 'robot':
                nodes.append(Node(package='p', executable='real', name='a'))
                rate = 10
            else:
                nodes.append(Node(package='p', executable='sim', name='a'))
                rate = 20
            nodes.append(Node(package='p', executable='user', name='u',
                              parameters=[{'rate': rate}]))
            return LaunchDescription(nodes)
        """)
    result = load(path)
    by_exe = {i.executable: i for i in result.instances}
    assert sorted(by_exe) == ['real', 'sim', 'user']
    assert result.instances[-1].executable == 'user'

    assert any('only when' in n for n in by_exe['real'].unresolved)
    assert any('only when' in n for n in by_exe['sim'].unresolved)
    assert by_exe['user'].params == {}
    assert any('rate' in n for n in by_exe['user'].unresolved)
    assert any('not known statically' in n for n in result.unresolved)


def test_ros2_python_alternatives_and_early_returns(tmp_path):
    path = write(tmp_path, 'x.launch.py', """
        import random

        from launch import LaunchDescription
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node


        def generate_launch_description():
            # always False in Python: read as not known statically
            if LaunchConfiguration('x') == 'true':
                nodes = [Node(package='p', executable='a')]
            else:
                nodes = [Node(package='p', executable='b')]
            if random.random() > 0.5:
                return LaunchDescription([Node(package='p',
                                               executable='early')])
            return LaunchDescription(nodes + [Node(package='p',
                                                   executable='late')])
        """)
    result = load(path)
    by_exe = {i.executable: i for i in result.instances}
    assert [i.executable for i in result.instances] == [
        'early', 'a', 'b', 'late']
    assert len(by_exe['early'].unresolved) == 1
    assert len(by_exe['a'].unresolved) == 2   # early return, first if
    assert len(by_exe['late'].unresolved) == 1
    assert 'is false' in by_exe['b'].unresolved[1]


def test_ros2_python_loop_over_unknown_values(tmp_path):
    path = write(tmp_path, 'x.launch.py', """
        from launch import LaunchDescription
        from launch_ros.actions import Node
        import helpers


        def generate_launch_description():
            nodes = [Node(package='p', executable='first')]
            for robot in helpers.robots():
                nodes = nodes + [Node(package='p', executable='looped',
                                      name=robot, namespace='fleet')]
            return LaunchDescription(nodes)
        """)
    result = load(path)
    first, looped = result.instances
    assert (first.executable, first.unresolved) == ('first', [])
    assert (looped.executable, looped.name, looped.namespace) == (
        'looped', None, '/fleet')
    assert 'created in a loop' in looped.unresolved[0]


def test_ros2_python_top_level_code_is_never_run(tmp_path):
    marker = tmp_path / 'written_at_import'
    inside = tmp_path / 'written_in_function'
    path = write(tmp_path, 'x.launch.py', f"""
        import subprocess

        from launch import LaunchDescription
        from launch_ros.actions import Node

        with open({str(marker)!r}, 'w') as f:
            f.write('executed')
        open({str(marker)!r}, 'w').write('executed')
        subprocess.run(['touch', {str(marker)!r}])
        EXE = __import__('os').system('touch ' + {str(marker)!r})


        def generate_launch_description():
            open({str(inside)!r}, 'w').write('executed')
            exec("open({str(inside)!r}, 'w')")
            return LaunchDescription([Node(package='p', executable='n')])
        """)
    result = load(path)
    assert not marker.exists() and not inside.exists()
    assert [i.executable for i in result.instances] == ['n']
    notes = '\n'.join(result.unresolved)
    assert 'module-level With statement not interpreted' in notes
    assert 'open() not interpreted' in notes


def test_ros2_python_includes_and_sources(tmp_path):
    write(tmp_path, 'pkg/launch/child.launch.py', """
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('name', default_value='child'),
                Node(package='p', executable='c',
                     name=LaunchConfiguration('name'),
                     remappings=[('in', LaunchConfiguration('topic',
                                                            default='x'))]),
            ])
        """)
    path = write(tmp_path, 'pkg/launch/top.launch.py', """
        import os

        from ament_index_python.packages import get_package_share_directory
        from launch import LaunchDescription
        from launch.actions import GroupAction, IncludeLaunchDescription
        from launch.launch_description_sources import (
            PythonLaunchDescriptionSource)
        from launch.substitutions import PathJoinSubstitution
        from launch.substitutions import ThisLaunchFileDir
        from launch_ros.actions import PushRosNamespace
        from launch_ros.substitutions import FindPackageShare


        def generate_launch_description():
            by_dir = IncludeLaunchDescription(PythonLaunchDescriptionSource(
                [ThisLaunchFileDir(), '/child.launch.py']),
                launch_arguments=[('name', 'one')])
            by_share = IncludeLaunchDescription(
                PythonLaunchDescriptionSource(PathJoinSubstitution([
                    FindPackageShare('pkg'), 'launch', 'child.launch.py'])),
                launch_arguments={'name': 'two', 'topic': 'y'}.items())
            by_ament = IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(
                    get_package_share_directory('pkg'), 'launch',
                    'child.launch.py')))
            missing = IncludeLaunchDescription(
                PythonLaunchDescriptionSource('/no/such/file.launch.py'))
            return LaunchDescription([
                by_dir,
                GroupAction([PushRosNamespace('g'), by_share]),
                by_ament, missing])
        """)
    result = load(path, package_paths={'pkg': tmp_path / 'pkg'})
    found = instances(result)
    assert sorted(found) == ['/child', '/g/two', '/one']
    assert found['/g/two'].remaps == [('in', 'y')]
    assert found['/one'].remaps == [('in', 'x')]
    assert 'file.launch.py not found' in '\n'.join(result.unresolved)


def test_ros2_python_malformed(tmp_path):
    path = write(tmp_path, 'bad.launch.py', 'def generate(:\n')
    with pytest.raises(LaunchError, match='bad.launch.py: not valid Python'):
        load(path)
