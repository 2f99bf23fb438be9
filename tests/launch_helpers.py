# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Helpers of the launch tests (tests/launch/): its files, loading, writing."""

from pathlib import Path
import textwrap

from colcon_rsia.launch import load_launch

FILES = Path(__file__).resolve().parent / 'launch' / 'launch_files'
ROS1_PKG = FILES / 'ros1_ws' / 'sysbot_bringup'
ROS2_PKG = FILES / 'ros2_ws' / 'robot_bringup'


def instances(result):
    """Instances by fully qualified name ('?' for unknown parts)."""
    out = {}
    for i in result.instances:
        ns = i.namespace if i.namespace is not None else '?'
        name = i.name if i.name is not None else '?'
        out[(ns.rstrip('/') + '/' + name)] = i
    return out


def write(directory, name, text):
    """Write `text`, dedented, to `directory`/`name`; return its path."""
    path = Path(directory) / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text).lstrip())
    return path


def load(path, **kwargs):
    """Load a launch file with an empty environment unless told."""
    kwargs.setdefault('environ', {})
    return load_launch(path, **kwargs)


def one_sentence(error):
    """The error's message, checked to be one sentence on one line."""
    message = str(error)
    assert '\n' not in message
    assert message.endswith('.')
    return message
