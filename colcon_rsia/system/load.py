# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The deployed system: summaries plus, optionally, a launch file."""

import os

from colcon_rsia.system import hosts
from colcon_rsia.system.graph import build_graph
from colcon_rsia.system.graph import Instance
from colcon_rsia.system.graph import loaded_nodelets
from colcon_rsia.system.names import join


class LaunchArgumentError(ValueError):
    """The --launch arguments do not name a launch file."""


def split_launch_arguments(words, package_paths):
    """Read ``FILE [name:=value …]`` or ``PKG FILE [name:=value …]``.

    :returns: (path of the launch file, {name: value})
    :raises LaunchArgumentError: when no launch file is found
    """
    positional = [w for w in words if ':=' not in w]
    arguments = dict(w.split(':=', 1) for w in words if ':=' in w)
    if len(positional) == 1 and os.path.isfile(positional[0]):
        return os.path.abspath(positional[0]), arguments
    if len(positional) == 1:
        raise _missing_launch_file(positional[0])
    if len(positional) == 2:
        package, name = positional
        if package not in package_paths and os.path.isfile(package):
            raise LaunchArgumentError(
                f'--launch {package}: a launch file takes only name:=value '
                f"arguments, got '{name}'")
        if package not in package_paths:
            raise LaunchArgumentError(
                f"unknown package '{package}' for --launch (the packages "
                'found under --base-paths are searched)')
        found = find_launch_file(package_paths[package], name)
        if found is None:
            raise LaunchArgumentError(
                f"no launch file '{name}' in package '{package}'")
        return found, arguments
    raise LaunchArgumentError(
        '--launch takes FILE or PKG FILE, then any name:=value arguments; '
        f'got {" ".join(words)!r}')


def _missing_launch_file(path):
    if os.path.exists(path):
        return LaunchArgumentError(
            f'--launch {path}: not a regular file; give a launch file')
    return LaunchArgumentError(
        f'--launch {path}: file not found (or give PKG FILE to find a '
        'launch file in a package)')


def find_launch_file(package_path, name):
    """A launch file of a package, as ``roslaunch pkg file`` finds it."""
    direct = os.path.join(package_path, name)
    if os.path.isfile(direct):
        return direct
    for directory in ('launch', ''):
        candidate = os.path.join(package_path, directory, name)
        if os.path.isfile(candidate):
            return candidate
    for root, dirs, files in os.walk(package_path):
        dirs[:] = [d for d in dirs if not d.startswith('.')]
        if os.path.basename(name) in files:
            return os.path.join(root, os.path.basename(name))
    return None


def launch_instances(summaries, result):
    """Match launched node instances with the analysed nodes.

    An executable that runs several nodes (one per node class) gives one
    instance per node, each under the name its code gives.

    :param result: a :class:`colcon_rsia.launch.LaunchResult`
    :returns: the instances and notes on what could not be matched
    """
    nodes = {}
    every_node = [n for s in summaries for n in s.nodes]
    plugins = [n for n in every_node if n.kind == 'plugin']
    # a component is launched by its class: the node that runs it (a
    # component, or the executable that only instantiates the class)
    by_class = {}
    for summary in summaries:
        for node in summary.nodes:
            nodes.setdefault((node.package, node.executable), []).append(node)
            nodes.setdefault((node.package, node.id), []).append(node)
            if node.plugin_class and node.kind != 'plugin':
                by_class.setdefault(
                    (node.package, node.plugin_class), []).append(node)
    instances = []
    notes = list(result.unresolved)
    for launched in result.instances:
        if launched.kind in ('nodelet_manager', 'container'):
            continue  # they host nodes; they publish nothing of their own
        package = launched.package or '?'
        executable = launched.executable or '?'
        matched = nodes.get((package, executable)) or (
            by_class.get((package, executable.lstrip(':')))
            if launched.kind == 'component' else None) or [None]
        for node in matched:
            instance = _launched_instance(
                launched, node, package, executable, several=len(matched) > 1)
            if node is None:
                notes.append(
                    f'{instance.id} ({package}/{executable}, '
                    f'{launched.location}): not analysed; assumed to read '
                    'and write its remapped topics')
            for note in launched.unresolved:
                notes.append(f'{instance.id}: {note}')
            instances.append(instance)
            instances += _hosted_instances(
                instance, plugins, notes, launched, result.global_params)
            instances += loaded_nodelets(instance, every_node)
    return instances, notes


def _hosted_instances(host, plugins, notes, launched, global_params):
    """The plugins a launched host loads, as the parameters name them.

    A ros2_control controller is a node of its own, named after its key in
    the controller manager's parameters; a navigation plugin runs in its
    server's node (its id is the server's name, then the plugin's). Either
    way the host's remaps apply. A ROS 1 spawner's controllers are nodes
    named after them in the spawner's namespace.
    """
    found = hosts.spawned_controllers(
        host.package, host.executable, launched.args, host.namespace,
        global_params)
    style = hosts.OWN_NODE
    if found is None:
        found = hosts.hosted_plugins(
            host.package, host.executable, host.params)
        if found:
            style = hosts.LAUNCHED_HOSTS[(host.package, host.executable)].style
    if not found:
        return []
    hosted = []
    for name, plugin_type in found:
        node = _plugin_node(plugins, plugin_type)
        instance = Instance(
            id='', node=node,
            package=node.package if node is not None else
            plugin_type.replace('::', '/').split('/')[0],
            executable=node.executable if node is not None else plugin_type,
            name=name if style == hosts.OWN_NODE else host.name,
            namespace=host.namespace, remaps=list(host.remaps),
            location=host.location)
        instance.id = instance.fqn if style == hosts.OWN_NODE \
            else f'{instance.fqn}/{name}'
        if node is None:
            # a plugin of a package outside the workspace, like a launched
            # executable that was not analysed
            notes.append(f'{instance.id} (plugin {plugin_type} of '
                         f'{host.id}): not analysed')
        hosted.append(instance)
    return hosted


def _plugin_node(plugins, plugin_type):
    """The plugin node a host's type name names (``pkg/Name``, ``ns::C``)."""
    wanted = plugin_type.strip().lstrip(':')
    as_class = wanted.replace('/', '::')
    for node in plugins:
        if node.id == wanted or node.plugin_class == as_class:
            return node
    return None


def _launched_instance(launched, node, package, executable, several):
    # unnamed in the launch file: the name the code gives, as at run time;
    # one launch name for several nodes of a process would clash, so each
    # of them keeps its own
    code_name = node.name if node is not None else None
    if several:
        name = code_name or node.id.split('/')[-1]
    else:
        name = launched.name or code_name or executable.split('/')[-1]
    # a launch file that leaves a ROS 2 node in the root namespace passes
    # no namespace: the code's stands (an explicit namespace="/" would
    # override it; the launch readers do not tell the two apart)
    namespace = launched.namespace
    if namespace in (None, '/') and node is not None and node.namespace:
        namespace = join('/', node.namespace)
    instance = Instance(
        id='', node=node, package=package, executable=executable,
        name=name, namespace=namespace or '/',
        remaps=list(launched.remaps), params=dict(launched.params),
        location=launched.location)
    instance.id = instance.fqn
    return instance


def load_system(summaries, *, launch=None, package_paths=None):
    """Build the system graph, from a launch file when one is given.

    :param launch: the ``--launch`` words, or None
    :raises LaunchArgumentError: for --launch words naming no file
    :raises colcon_rsia.launch.LaunchError: for a launch file that cannot
      be read
    """
    if not launch:
        system = build_graph(summaries)
        launch_files = []
    else:
        from colcon_rsia.launch import load_launch
        path, arguments = split_launch_arguments(launch, package_paths or {})
        result = load_launch(
            path, arguments=arguments, package_paths=package_paths or {})
        instances, notes = launch_instances(summaries, result)
        system = build_graph(summaries, instances=instances, notes=notes)
        launch_files = list(result.files)
    # what `--since` maps changed files with: the launch and parameter files
    # read, and the source path each package's node files are relative to
    system.launch_files = launch_files
    system.package_sources = {s.package: s.path for s in summaries}
    return system
