# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A monitor per robot, made in a loop (unrolled statically)."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    nodes = []
    for index, topic in enumerate(['scan', 'odom']):
        nodes.append(Node(
            package='robot_monitor', executable='rate_monitor',
            name=f'monitor_{index}', arguments=['--ros-args', '-r',
                                                f'in:={topic}']))
    return LaunchDescription(nodes)
