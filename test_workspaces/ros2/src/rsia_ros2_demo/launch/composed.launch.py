# The two components of this package loaded into one container.
from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        ComposableNodeContainer(
            name='sensors', namespace='robot', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(
                    package='rsia_ros2_demo', plugin='rsia_demo::LidarComponent',
                    name='front_lidar', namespace='robot'),
                ComposableNode(
                    package='rsia_ros2_demo', plugin='rsia_demo::CameraComponent',
                    namespace='robot'),
            ]),
    ])
