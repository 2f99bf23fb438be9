# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Launched host processes and the plugins their parameters load.

The query-time half of the host table (the build-time half,
:mod:`colcon_rsia.package.plugin_hosts`, says how a host calls a plugin's
methods): with ``--launch``, a controller manager or a navigation server
instance loads the plugins its parameters name, and each runs either as a
node of its own or inside the host's node.
"""

from dataclasses import dataclass

from colcon_rsia.system.names import join


@dataclass(frozen=True)
class LaunchedHost:
    """How a launched host process names the plugins it loads.

    ``own_node``: each plugin is a node of its own, named after the key it
    has in the host's parameters, in the host's namespace (a ros2_control
    controller: ``<name>.type: pkg/Class``). ``in_host``: the plugins run
    in the host's node, listed by ``list_parameter`` (default
    ``default_names``), each with ``<name>.plugin: pkg::Class``.
    """

    style: str
    type_key: str
    list_parameter: str = ''
    default_names: tuple = ()


OWN_NODE = 'own_node'
IN_HOST = 'in_host'

# (package, executable) of a host process -> how it names its plugins;
# the navigation servers' defaults are their documented ones
LAUNCHED_HOSTS = {
    ('controller_manager', 'ros2_control_node'): LaunchedHost(
        OWN_NODE, 'type'),
    ('nav2_controller', 'controller_server'): LaunchedHost(
        IN_HOST, 'plugin', 'controller_plugins', ('FollowPath',)),
    ('nav2_planner', 'planner_server'): LaunchedHost(
        IN_HOST, 'plugin', 'planner_plugins', ('GridBased',)),
    ('nav2_smoother', 'smoother_server'): LaunchedHost(
        IN_HOST, 'plugin', 'smoother_plugins', ()),
    ('nav2_behaviors', 'behavior_server'): LaunchedHost(
        IN_HOST, 'plugin', 'behavior_plugins', ()),
}


# ROS 1: a spawner asks the robot's controller manager to load the
# controllers it names; their types are global parameters `<name>/type`
ROS1_SPAWNERS = {
    ('controller_manager', 'spawner'): 0,
    # `controller_manager spawn|load NAME ...`
    ('controller_manager', 'controller_manager'): 1,
}


def spawned_controllers(package, executable, args, namespace,
                        global_params):
    """[(controller name, type)] a launched ROS 1 spawner loads, or None.

    A name whose type no parameter of the launch files gives is left out.
    """
    skip = ROS1_SPAWNERS.get((package, executable))
    if skip is None or (skip and args[:1] not in (['spawn'], ['load'])):
        return None
    for word in args:
        if word.startswith('--namespace='):
            value = word.split('=', 1)[1]
            namespace = value if value.startswith('/') \
                else join(namespace or '/', value)
    found = []
    for name in args[skip:]:
        if name.startswith('-'):
            continue
        value = global_params.get(join(namespace or '/', f'{name}/type'))
        if isinstance(value, str):
            found.append((name, value))
    return found


def hosted_plugins(package, executable, params):
    """[(plugin name, plugin type)] a launched host's parameters load.

    :param params: the host instance's parameters (``a.b`` for nested keys)
    :returns: None when the process is no host of the table
    """
    host = LAUNCHED_HOSTS.get((package, executable))
    if host is None:
        return None
    if host.style == OWN_NODE:
        suffix = '.' + host.type_key
        return sorted(
            (key[:-len(suffix)], str(value)) for key, value in params.items()
            if key.endswith(suffix) and key.count('.') == 1 and
            isinstance(value, str))
    names = params.get(host.list_parameter, list(host.default_names))
    if isinstance(names, str):
        names = [names]
    found = []
    for name in names if isinstance(names, list) else []:
        value = params.get(f'{name}.{host.type_key}')
        if isinstance(value, str):
            found.append((str(name), value))
    return found
