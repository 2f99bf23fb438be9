# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The ROS 2 launch model: the values and actions a launch file is read into.

The XML and YAML readers (:mod:`colcon_rsia.launch.ros2`) and the Python
reader (:mod:`colcon_rsia.launch.python_launch`) produce these; the
executor (:class:`colcon_rsia.launch.ros2_executor.Ros2Executor`) runs
them. Plain data: nothing here reads a file or resolves a value.

A class has the name of the ROS 2 launch class (``launch``,
``launch_ros``) of the same concept, so that a reader of a ``.launch.py``
file finds the class it builds under the name the file calls. A class
that stands for several launch classes (:class:`PackagePath`,
:class:`ThisFile`, :class:`BoolOp`, :class:`SetEnv`) or for none
(:class:`Opaque`, :class:`Ignored`, :class:`ParamItem`…) has a name of its
own. :class:`Condition` is the launch ``Condition`` of every kind: its
``kind`` says which.
"""

from dataclasses import dataclass
from dataclasses import field
from typing import List


# values (substitutions written in Python)


@dataclass
class UnknownValue:
    """A value not known statically (the reason says why)."""

    reason: str


@dataclass
class LaunchConfiguration:
    """``LaunchConfiguration('name', default=…)``."""

    name: object
    default: object = None


@dataclass
class PackagePath:
    """``FindPackageShare`` / ``FindPackagePrefix``."""

    package: object
    kind: str = 'share'


@dataclass
class EnvironmentVariable:
    """``EnvironmentVariable(name, default_value=…)``."""

    name: object
    default: object = None


@dataclass
class PathJoinSubstitution:
    """``PathJoinSubstitution([...])``."""

    parts: list


@dataclass
class PythonExpression:
    """``PythonExpression([...])`` (evaluated in the safe subset)."""

    parts: list


@dataclass
class ThisFile:
    """``ThisLaunchFile()`` / ``ThisLaunchFileDir()``."""

    directory: bool


@dataclass
class BoolOp:
    """Not/And/Or/Equals/NotEquals/IfElse substitutions."""

    op: str
    operands: list


@dataclass
class TypedValue:
    """``ParameterValue(value, value_type=str)``: kept as text."""

    value: object


# conditions


@dataclass
class Condition:
    """A launch condition: if/unless a value, or a configuration equality.

    ``IfCondition``, ``UnlessCondition``, ``LaunchConfigurationEquals``,
    ``LaunchConfigurationNotEquals`` and the ``if``/``unless`` attributes.
    """

    kind: str  # 'if', 'unless', 'equals', 'not_equals', 'unknown'
    operands: list


# actions


@dataclass
class Action:
    """Common fields of the actions."""

    location: str = ''
    conditions: list = field(default_factory=list)
    notes: List[str] = field(default_factory=list)


@dataclass
class DeclareLaunchArgument(Action):
    """``<arg>`` / ``DeclareLaunchArgument``."""

    name: object = None
    default: object = None
    has_default: bool = False


@dataclass
class SetLaunchConfiguration(Action):
    """``<let>`` / ``SetLaunchConfiguration``."""

    name: object = None
    value: object = None


@dataclass
class ParamDict:
    """A parameter dictionary written in Python: (name, value) pairs."""

    pairs: list


@dataclass
class ParamItem:
    """One entry of a node's parameters."""

    kind: str  # 'value' (name, value), 'dict', 'file', 'unknown'
    name: object = None
    value: object = None
    allow_substs: bool = False


@dataclass
class ComposableNode(Action):
    """``<composable_node>`` / ``ComposableNode``."""

    package: object = None
    plugin: object = None
    name: object = None
    namespace: object = None
    remaps: list = field(default_factory=list)
    params: List[ParamItem] = field(default_factory=list)


@dataclass
class Node(Action):
    """``<node>``, ``<node_container>`` / ``Node`` and its kinds.

    ``LifecycleNode`` and ``ComposableNodeContainer`` (the launch classes
    derived from ``Node``) are the kinds ``lifecycle`` and ``container``.
    """

    package: object = None
    executable: object = None
    name: object = None
    namespace: object = None
    remaps: list = field(default_factory=list)
    params: List[ParamItem] = field(default_factory=list)
    arguments: list = field(default_factory=list)
    ros_arguments: list = field(default_factory=list)
    kind: str = 'node'
    composables: list = field(default_factory=list)


@dataclass
class LoadComposableNodes(Action):
    """``<load_composable_node>`` / ``LoadComposableNodes``."""

    composables: list = field(default_factory=list)


@dataclass
class IncludeLaunchDescription(Action):
    """``<include>`` / ``IncludeLaunchDescription``."""

    path: object = None
    arguments: list = field(default_factory=list)  # (name, value)


@dataclass
class GroupAction(Action):
    """``<group>`` / ``GroupAction`` (also timers and event handlers)."""

    actions: list = field(default_factory=list)
    scoped: object = True
    forwarding: bool = True
    configurations: list = field(default_factory=list)  # (name, value)


@dataclass
class PushROSNamespace(Action):
    """``<push-ros-namespace>`` / ``PushROSNamespace``.

    (and ``PushRosNamespace``, the action's older name)
    """

    namespace: object = None


@dataclass
class SetRemap(Action):
    """``<set_remap>`` / ``SetRemap``."""

    source: object = None
    target: object = None


@dataclass
class SetParameter(Action):
    """``<set_parameter>`` / ``SetParameter``."""

    name: object = None
    value: object = None


@dataclass
class SetEnv(Action):
    """``<set_env>``/``<unset_env>`` and their Python actions."""

    name: object = None
    value: object = None  # None: unset


@dataclass
class Opaque(Action):
    """Something that is not analysed; its note is reported."""

    note: str = ''


@dataclass
class Ignored(Action):
    """An action without effect on the node graph (LogInfo…)."""
