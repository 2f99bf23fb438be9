# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The robot: sensors, navigation and a camera pipeline in components."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.actions import GroupAction
from launch.actions import IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import ComposableNodeContainer
from launch_ros.actions import LoadComposableNodes
from launch_ros.actions import Node
from launch_ros.actions import PushRosNamespace
from launch_ros.actions import SetRemap
from launch_ros.descriptions import ComposableNode
from launch_ros.substitutions import FindPackageShare

PACKAGE = 'robot_bringup'
CONTROL_RATE = 50.0


def camera(name, fps=30):
    return ComposableNode(
        package='robot_camera', plugin='robot_camera::Driver', name=name,
        parameters=[{'fps': fps}], remappings=[('image', 'image_raw')])


def generate_launch_description():
    share = get_package_share_directory(PACKAGE)
    robot = LaunchConfiguration('robot')
    launch_dir = os.path.join(share, 'launch')
    args = [
        DeclareLaunchArgument('robot', default_value='robot1'),
        DeclareLaunchArgument('nav', default_value='true'),
        DeclareLaunchArgument('lidar_rate', default_value='15'),
    ]
    controller = Node(
        package='robot_control', executable='controller', name='controller',
        parameters=[
            {'rate': CONTROL_RATE, 'base_frame': [robot, '/base_link'],
             'gains': {'p': 1.0, 'd': 0.1}},
            PathJoinSubstitution([FindPackageShare(PACKAGE), 'config',
                                  'nav_params.yaml']),
        ],
        remappings=[('cmd_vel', 'cmd_vel_safe'), ('odom', '/odom')])
    sensors = IncludeLaunchDescription(
        AnyLaunchDescriptionSource(
            os.path.join(launch_dir, 'sensors.launch.xml')),
        launch_arguments={'lidar_rate': LaunchConfiguration('lidar_rate'),
                          'frame': 'lidar_link'}.items())
    navigation = IncludeLaunchDescription(
        AnyLaunchDescriptionSource(
            os.path.join(launch_dir, 'navigation.launch.yaml')),
        condition=IfCondition(LaunchConfiguration('nav')))
    container = ComposableNodeContainer(
        name='camera_container', namespace='',
        package='rclcpp_components', executable='component_container',
        composable_node_descriptions=[camera('front'), camera('rear', 15)])
    extra = LoadComposableNodes(
        target_container='camera_container',
        composable_node_descriptions=[
            ComposableNode(package='robot_vision',
                           plugin='robot_vision::Detector',
                           name='detector', namespace='vision')])
    ld = LaunchDescription(args)
    ld.add_action(GroupAction([
        PushRosNamespace(robot),
        SetRemap(src='/tf', dst='tf'),
        sensors,
        controller,
        navigation,
        container,
        extra,
    ]))
    ld.add_action(IncludeLaunchDescription(PythonLaunchDescriptionSource(
        os.path.join(launch_dir, 'monitor.launch.py'))))
    return ld
