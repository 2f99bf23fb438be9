# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The frameworks that load plugins, and how they call a plugin's methods.

A pluginlib class (a controller, a planner, a costmap layer) is no process
of its own: a host (the controller manager, a navigation server) loads it
and calls its methods. Which methods, and how, decides its publishers'
labels, since nothing in the plugin's own code calls them:

- ``periodic``: the host calls the method from its own fixed-rate loop
  (the controller manager's ``update_rate``, the controller server's
  ``controller_frequency``). A publish reached only from such a method is
  independent of the plugin's inputs: pattern ``host_periodic``.
- ``requests``: the host calls the method when a request reaches it (an
  action goal, a service call): an input of the plugin, like a service
  callback, so what it publishes is dependent.
- ``setup``: lifecycle and configuration methods; roots that run once.

Facts from the frameworks' interfaces and documentation: ros2_control
(``controller_interface/controller_interface_base.hpp``,
``hardware_interface/system_interface.hpp``), ros_control
(``controller_interface/controller_base.h``), pr2_controller_interface,
the navigation2 plugin interfaces and server parameters (docs.nav2.org),
ROS 1 nav_core / costmap_2d, and Gazebo classic's plugin and event
interfaces (``gazebo/common/Plugin.hh``, ``gazebo/common/Events.hh``).
"""

from dataclasses import dataclass

from colcon_rsia.summary.kinds import ROOT_HOST_PERIODIC
from colcon_rsia.summary.kinds import ROOT_HOST_REQUEST
from colcon_rsia.summary.kinds import ROOT_HOST_SETUP


@dataclass(frozen=True)
class Host:
    """How one framework hosts the plugins of one base class."""

    host: str                # the process that loads the plugin
    periodic: frozenset      # methods called from the host's fixed-rate loop
    requests: frozenset      # methods called when a request arrives
    setup: frozenset         # lifecycle / configuration methods
    rate_parameter: str      # the host parameter that sets the period
    # the method whose last parameter is the NodeHandle the host gives the
    # plugin in its own namespace (a ROS 1 controller's controller_nh)
    private_handle_of: str = ''
    # the host's events whose callbacks it calls from its loop: the APIs
    # (ros_api.HOST_EVENT) the plugin connects them with
    periodic_events: frozenset = frozenset()


def _names(text):
    return frozenset(text.split())


_ROS2_CONTROLLER = Host(
    host='controller_manager',
    periodic=_names('update update_and_write_commands '
                    'update_reference_from_subscribers'),
    requests=frozenset(),
    setup=_names('on_init on_configure on_activate on_deactivate on_cleanup '
                 'on_error on_shutdown command_interface_configuration '
                 'state_interface_configuration on_export_state_interfaces '
                 'on_export_reference_interfaces on_set_chained_mode'),
    rate_parameter='update_rate')
_ROS2_HARDWARE = Host(
    host='controller_manager (resource manager)',
    periodic=_names('read write'),
    requests=frozenset(),
    setup=_names('on_init on_configure on_activate on_deactivate on_cleanup '
                 'on_error on_shutdown export_state_interfaces '
                 'export_command_interfaces prepare_command_mode_switch '
                 'perform_command_mode_switch'),
    rate_parameter='update_rate')
_ROS1_CONTROLLER = Host(
    host='controller_manager',
    periodic=_names('update'),
    requests=frozenset(),
    setup=_names('init initRequest starting stopping waiting aborting'),
    rate_parameter="the hardware interface node's control loop",
    private_handle_of='init')
_NAV2_CONTROLLER = Host(
    host='controller_server',
    periodic=_names('computeVelocityCommands'),
    requests=_names('setPlan cancel setSpeedLimit'),
    setup=_names('configure activate deactivate cleanup reset'),
    rate_parameter='controller_frequency (default 20 Hz)')
_NAV2_CHECKER = Host(
    host='controller_server',
    periodic=_names('isGoalReached check'),
    requests=frozenset(),
    setup=_names('initialize reset'),
    rate_parameter='controller_frequency (default 20 Hz)')
_NAV2_PLANNER = Host(
    host='planner_server',
    periodic=frozenset(),
    requests=_names('createPlan'),
    setup=_names('configure activate deactivate cleanup'),
    rate_parameter='')
_NAV2_SMOOTHER = Host(
    host='smoother_server',
    periodic=frozenset(),
    requests=_names('smooth'),
    setup=_names('configure activate deactivate cleanup'),
    rate_parameter='')
_NAV2_BEHAVIOR = Host(
    host='behavior_server',
    # a timed behavior runs onCycleUpdate at cycle_frequency while active
    periodic=_names('onCycleUpdate'),
    requests=_names('onRun onActionCompletion'),
    setup=_names('configure activate deactivate cleanup onConfigure '
                 'onCleanup'),
    rate_parameter='cycle_frequency (default 10 Hz)')
_COSTMAP_LAYER = Host(
    host='costmap',
    periodic=_names('updateBounds updateCosts'),
    requests=frozenset(),
    setup=_names('initialize onInitialize activate deactivate reset '
                 'matchSize onFootprintChanged'),
    rate_parameter='update_frequency')
_ROS1_LOCAL_PLANNER = Host(
    host='move_base',
    periodic=_names('computeVelocityCommands isGoalReached'),
    requests=_names('setPlan'),
    setup=_names('initialize'),
    rate_parameter='controller_frequency')
_ROS1_GLOBAL_PLANNER = Host(
    host='move_base',
    periodic=frozenset(),
    requests=_names('makePlan'),
    setup=_names('initialize'),
    rate_parameter='')
_ROS1_RECOVERY = Host(
    host='move_base',
    periodic=frozenset(),
    requests=_names('runBehavior'),
    setup=_names('initialize'),
    rate_parameter='')

_BT_NODE = Host(
    host='bt_navigator',
    # the navigator ticks the tree every bt_loop_duration while a goal is
    # active; a node's tick (and the hooks its tick calls) run then
    periodic=_names('tick onStart onRunning on_tick on_wait_for_result '
                    'on_success on_aborted on_cancelled'),
    requests=frozenset(),
    setup=_names('halt onHalted providedPorts'),
    rate_parameter='bt_loop_duration (default 10 ms)')

# gzserver loads model, sensor, world and system plugins: it calls Load()
# once, and every callback connected to its world-update events on every
# simulation step (gazebo/common/Plugin.hh, gazebo/common/Events.hh)
_GAZEBO = Host(
    host='gzserver',
    periodic=frozenset(),
    requests=frozenset(),
    setup=_names('Load Init Reset'),
    rate_parameter="every simulation step: the world's physics "
                   'real_time_update_rate',
    periodic_events=_names(
        'gazebo::event::Events::ConnectWorldUpdateBegin '
        'gazebo::event::Events::ConnectWorldUpdateEnd '
        'gazebo::event::Events::ConnectBeforePhysicsUpdate'))

# the base class a plugin is exported with -> its host
HOSTS = {
    # any node registered with BT_REGISTER_NODES (see frontend/cpp/plugin_exports.py)
    'BT::TreeNode': _BT_NODE,
    'controller_interface::ControllerInterface': _ROS2_CONTROLLER,
    'controller_interface::ChainableControllerInterface': _ROS2_CONTROLLER,
    'controller_interface::ControllerInterfaceBase': _ROS2_CONTROLLER,
    'hardware_interface::SystemInterface': _ROS2_HARDWARE,
    'hardware_interface::ActuatorInterface': _ROS2_HARDWARE,
    'hardware_interface::SensorInterface': _ROS2_HARDWARE,
    'controller_interface::ControllerBase': _ROS1_CONTROLLER,
    'controller_interface::Controller': _ROS1_CONTROLLER,
    'controller_interface::MultiInterfaceController': _ROS1_CONTROLLER,
    'pr2_controller_interface::Controller': _ROS1_CONTROLLER,
    'nav2_core::Controller': _NAV2_CONTROLLER,
    'nav2_core::GoalChecker': _NAV2_CHECKER,
    'nav2_core::ProgressChecker': _NAV2_CHECKER,
    'nav2_core::GlobalPlanner': _NAV2_PLANNER,
    'nav2_core::Smoother': _NAV2_SMOOTHER,
    'nav2_core::Behavior': _NAV2_BEHAVIOR,
    'nav2_costmap_2d::Layer': _COSTMAP_LAYER,
    'costmap_2d::Layer': _COSTMAP_LAYER,
    'nav_core::BaseLocalPlanner': _ROS1_LOCAL_PLANNER,
    'nav_core::BaseGlobalPlanner': _ROS1_GLOBAL_PLANNER,
    'nav_core::RecoveryBehavior': _ROS1_RECOVERY,
    # registered with GZ_REGISTER_*_PLUGIN (see frontend/cpp/plugin_exports.py)
    'gazebo::ModelPlugin': _GAZEBO,
    'gazebo::SensorPlugin': _GAZEBO,
    'gazebo::WorldPlugin': _GAZEBO,
    'gazebo::SystemPlugin': _GAZEBO,
}


def host_of(base_class):
    """The host of the plugins exported with `base_class`, or None.

    Template arguments and a leading ``::`` do not matter.
    """
    name = base_class.split('<', 1)[0].strip().lstrip(':')
    return HOSTS.get(name)


def root_kind(host, method_name):
    """The root kind the host gives a plugin method, or None."""
    if host is None:
        return None
    if method_name in host.periodic:
        return ROOT_HOST_PERIODIC
    if method_name in host.requests:
        return ROOT_HOST_REQUEST
    if method_name in host.setup:
        return ROOT_HOST_SETUP
    return None
