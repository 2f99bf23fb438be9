"""Sensor part of the Fig. 2 deployment, ROS 2 Python launch file.

Included by robot.launch.py inside a GroupAction that pushes the namespace
"sensors". Same instances and topics as sensors.launch; ROS 2 has no
namespace-level parameters, so sensors.launch's <param name="topic"> outside any
node (a no-op there) has no counterpart here.
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('camera_ns', default_value='camera'),

        Node(package='cob_sensors', executable='laser_scanner', name='laser_front',
             remappings=[('scan', 'scan_front')]),
        Node(package='cob_sensors', executable='laser_scanner', name='laser_rear',
             remappings=[('scan', 'scan_rear')]),

        # Parameter-based output topic, set.
        Node(package='cob_processing', executable='scan_filter', name='filter_front',
             remappings=[('input', 'scan_front')],
             parameters=[{'topic': 'scan_front_filtered'}]),

        # Default "filtered"; relative namespace "rear" under the pushed "sensors".
        Node(package='cob_processing', executable='scan_filter', name='filter',
             namespace='rear',
             remappings=[('input', '/sensors/scan_rear')]),

        Node(package='cob_sensors', executable='camera', name='driver',
             namespace=LaunchConfiguration('camera_ns')),
    ])
