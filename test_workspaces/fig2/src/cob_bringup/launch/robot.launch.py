"""Fig. 2 style deployment, ROS 2 Python launch file.

The same instances and topics as robot.launch (ROS 1), robot.launch.xml and
robot.launch.yaml. Groups push their namespace with PushRosNamespace, the
group-level remap is a SetRemap inside a scoped GroupAction, the rviz node is
conditional on the launch argument use_rviz.
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace, SetRemap
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    use_rviz = LaunchConfiguration('use_rviz')
    camera_ns = LaunchConfiguration('camera_ns')
    camera_image = ['/sensors/', camera_ns, '/image']

    sensors = GroupAction([
        PushRosNamespace('sensors'),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(PathJoinSubstitution(
                [FindPackageShare('cob_bringup'), 'launch', 'sensors.launch.py'])),
            launch_arguments={'camera_ns': camera_ns}.items()),
    ])

    navigation = GroupAction([
        PushRosNamespace('navigation'),
        Node(package='cob_processing', executable='merger', name='scan_unifier',
             remappings=[('in_a', '/sensors/scan_front_filtered'),
                         ('in_b', '/sensors/rear/filtered'),
                         ('merged', 'scan_unified')]),
        # Scoped group-level remap for the two nodes inside it only.
        GroupAction([
            SetRemap(src='input', dst='scan_unified'),
            Node(package='cob_processing', executable='rate_loop_node', name='localization',
                 remappings=[('output', 'pose')]),
            Node(package='cob_processing', executable='throttle', name='costmap',
                 remappings=[('output', 'costmap')]),
        ]),
        Node(package='cob_processing', executable='merger', name='planner',
             remappings=[('in_a', 'costmap'),
                         ('in_b', '/perception/tracks'),
                         ('merged', 'plan')]),
        Node(package='cob_processing', executable='relay', name='path_follower',
             remappings=[('input', 'plan'), ('output', 'cmd_vel_raw')]),
        Node(package='cob_processing', executable='merger', name='collision_filter',
             remappings=[('in_a', 'cmd_vel_raw'),
                         ('in_b', 'scan_unified'),
                         ('merged', '/base/cmd_vel')]),
    ])

    base = GroupAction([
        PushRosNamespace('base'),
        Node(package='cob_processing', executable='rate_loop_node', name='base_driver',
             remappings=[('input', 'cmd_vel'), ('output', 'odom')]),
        Node(package='cob_processing', executable='throttle', name='odom_throttle',
             remappings=[('input', 'odom'), ('output', 'odom_slow')]),
        Node(package='cob_processing', executable='throttle', name='odom_tf',
             remappings=[('input', 'odom'), ('output', '/tf')]),
    ])

    manipulation = GroupAction([
        PushRosNamespace('manipulation'),
        Node(package='cob_processing', executable='merger', name='arm_planner',
             remappings=[('in_a', '/navigation/pose'),
                         ('in_b', '/perception/tracks'),
                         ('merged', 'arm_goal')]),
        Node(package='cob_processing', executable='rate_loop_node', name='arm_controller',
             remappings=[('input', 'arm_goal'), ('output', 'joint_states')]),
        Node(package='cob_processing', executable='relay', name='joint_relay',
             remappings=[('input', 'joint_states'), ('output', '/joint_states')]),
    ])

    perception = GroupAction([
        PushRosNamespace('perception'),
        Node(package='cob_processing', executable='relay', name='people_detector',
             remappings=[('input', camera_image), ('output', 'people')]),
        Node(package='cob_processing', executable='throttle', name='people_tracker',
             remappings=[('input', 'people'), ('output', 'tracks')]),
    ])

    ui = GroupAction([
        PushRosNamespace('ui'),
        Node(package='cob_processing', executable='relay', name='image_relay',
             remappings=[('input', camera_image), ('output', 'image_web')]),
        Node(package='cob_processing', executable='sink', name='web_view',
             remappings=[('input', 'image_web')]),
        # Not in the workspace: unknown node.
        Node(package='rviz', executable='rviz', name='rviz',
             condition=IfCondition(use_rviz),
             remappings=[('scan', '/navigation/scan_unified'), ('image', 'image_web')]),
    ])

    # Node-level namespace instead of a group (ROS 1: ns= on <node>).
    monitors = [
        Node(package='cob_processing', executable='sink', name='scan_monitor',
             namespace='diagnostics', remappings=[('input', '/navigation/scan_unified')]),
        Node(package='cob_processing', executable='sink', name='odom_monitor',
             namespace='diagnostics', remappings=[('input', '/base/odom_slow')]),
        Node(package='cob_processing', executable='sink', name='tf_monitor',
             namespace='diagnostics', remappings=[('input', '/tf')]),
        Node(package='cob_processing', executable='sink', name='joint_monitor',
             namespace='diagnostics', remappings=[('input', '/joint_states')]),
    ]

    return LaunchDescription([
        DeclareLaunchArgument('use_rviz', default_value='true'),
        DeclareLaunchArgument('camera_ns', default_value='camera'),
        sensors,
        navigation,
        base,
        manipulation,
        perception,
        ui,
        *monitors,
    ])
