# A ROS 2 bringup read (never run) by colcon rsia --launch: a renamed and
# namespaced scan filter whose topics come from parameters, the two-node
# multi_node executable and the arm driver under the names its code gives.
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='rsia_ros2_core', executable='scan_filter',
             name='front_filter', namespace='front',
             parameters=[{'input_topic': '/lidar/front',
                          'output_topic': 'scan'}]),
        Node(package='rsia_ros2_core', executable='multi_node'),
        Node(package='rsia_ros2_core', executable='arm_driver'),
    ])
