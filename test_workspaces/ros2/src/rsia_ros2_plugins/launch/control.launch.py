# A controller manager hosting the two controllers of this package, a planner
# server hosting its planner, the relay of rsia_ros2_wrapped feeding the
# odometry controller's commands, and the odometry relay of rsia_ros2_core
# reading the controller's odometry.
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    config = PathJoinSubstitution([FindPackageShare('rsia_ros2_plugins'), 'config'])
    return LaunchDescription([
        Node(
            package='controller_manager', executable='ros2_control_node',
            name='controller_manager',
            parameters=[PathJoinSubstitution([config, 'controllers.yaml'])]),
        Node(
            package='controller_manager', executable='spawner',
            arguments=['odometry_controller', 'state_broadcaster']),
        Node(
            package='nav2_planner', executable='planner_server',
            name='planner_server',
            parameters=[PathJoinSubstitution([config, 'planner.yaml'])]),
        Node(
            package='rsia_ros2_wrapped', executable='velocity_relay',
            remappings=[('cmd_vel_out', '/odometry_controller/cmd_vel')]),
        Node(
            package='rsia_ros2_core', executable='odom_relay',
            remappings=[('odom_in', '/odometry_controller/odom')]),
    ])
