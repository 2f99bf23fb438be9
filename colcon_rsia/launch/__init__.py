# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Launch files -> the node instances a deployed system runs.

Launch files are read, never executed: XML through defusedxml, YAML through
``yaml.safe_load``, Python launch files through the stdlib ``ast`` (an
interpreter of a small subset that only builds launch actions), and
``$(eval …)`` in a small safe expression subset.
"""

import os

from colcon_rsia.launch.common import file_kind
from colcon_rsia.launch.common import Loader
from colcon_rsia.launch.model import LaunchError
from colcon_rsia.launch.model import LaunchResult
from colcon_rsia.launch.model import NodeInstance

__all__ = ['LaunchError', 'LaunchResult', 'NodeInstance', 'file_kind',
           'load_launch']


def load_launch(path, *, arguments=None, package_paths=None, environ=None):
    """Read a launch file and what it includes, without executing anything.

    :param path: the top-level launch file (ROS 1 XML, ROS 2 XML, YAML or
      Python)
    :param dict arguments: ``name:=value`` command-line arguments
    :param dict package_paths: package name -> source directory, for
      ``$(find pkg)`` and its ROS 2 relatives; installed packages are looked
      for under ``/opt/ros/*/share`` and ``/usr/share`` otherwise
    :param dict environ: the environment for ``$(env)``/``$(optenv)``;
      default: this process's environment
    :returns: a :class:`LaunchResult`
    :raises LaunchError: when the top-level file cannot be read, or a file
      is malformed or refused (DTD entities, external references)
    """
    path = os.fspath(path)
    loader = Loader(arguments=arguments, package_paths=package_paths,
                    environ=environ)
    if not os.path.isfile(path):
        raise LaunchError(f'{path}: launch file not found.')
    try:
        text, root, kind = loader.read_launch(path)
        loader.include_stack.append(os.path.realpath(path))
        if kind == 'ros1':
            from colcon_rsia.launch.ros1 import Ros1Reader
            Ros1Reader(loader).read_top(path, root)
        else:
            from colcon_rsia.launch.ros2_executor import Ros2Executor
            Ros2Executor(loader, _ros2_readers()).run_top(
                path, kind, text, root)
    except LaunchError:
        raise
    except RecursionError:
        raise LaunchError(f'{path}: launch files nested too deeply to '
                          'analyse.')
    except Exception as e:  # a bug of ours must not stop the caller
        raise LaunchError(
            f'{path}: internal error of the launch analysis '
            f'({type(e).__name__}: {e}); please report it.') from e
    return loader.result


def _ros2_readers():
    """The readers of ROS 2 launch files by kind, for the executor.

    Imported when a ROS 2 file is read: a ROS 1 system never loads them.
    """
    from colcon_rsia.launch.python_launch import read_python_launch
    from colcon_rsia.launch.ros2 import read_xml_launch
    from colcon_rsia.launch.ros2 import read_yaml_launch
    return {'ros2': read_xml_launch, 'yaml': read_yaml_launch,
            'python': read_python_launch}
