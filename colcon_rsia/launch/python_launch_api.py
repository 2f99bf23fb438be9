# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The launch and launch_ros API as the Python launch interpreter knows it.

Each entry of :data:`LAUNCH_API` turns a call of the launch library (by the
last part of its name) into the actions and values of
:mod:`colcon_rsia.launch.ir`.
"""

from dataclasses import dataclass

from colcon_rsia.launch.ir import BoolOp
from colcon_rsia.launch.ir import ComposableNode
from colcon_rsia.launch.ir import Condition
from colcon_rsia.launch.ir import DeclareLaunchArgument
from colcon_rsia.launch.ir import EnvironmentVariable
from colcon_rsia.launch.ir import GroupAction
from colcon_rsia.launch.ir import Ignored
from colcon_rsia.launch.ir import IncludeLaunchDescription
from colcon_rsia.launch.ir import LaunchConfiguration
from colcon_rsia.launch.ir import LoadComposableNodes
from colcon_rsia.launch.ir import Node
from colcon_rsia.launch.ir import Opaque
from colcon_rsia.launch.ir import PackagePath
from colcon_rsia.launch.ir import ParamDict
from colcon_rsia.launch.ir import ParamItem
from colcon_rsia.launch.ir import PathJoinSubstitution
from colcon_rsia.launch.ir import PushROSNamespace
from colcon_rsia.launch.ir import PythonExpression
from colcon_rsia.launch.ir import SetEnv
from colcon_rsia.launch.ir import SetLaunchConfiguration
from colcon_rsia.launch.ir import SetParameter
from colcon_rsia.launch.ir import SetRemap
from colcon_rsia.launch.ir import ThisFile
from colcon_rsia.launch.ir import TypedValue
from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.python_launch_values import EventHandler
from colcon_rsia.launch.python_launch_values import Function
from colcon_rsia.launch.python_launch_values import HashableValue
from colcon_rsia.launch.python_launch_values import LaunchDescription
from colcon_rsia.launch.python_launch_values import LaunchSource
from colcon_rsia.launch.python_launch_values import MAX_CODE_NESTING
from colcon_rsia.launch.python_launch_values import Ref
from colcon_rsia.launch.safe_eval import Unresolved


class ArgError(Exception):
    """A call of the launch API with arguments it does not take."""


class Args:
    """Positional and keyword arguments of a launch API call."""

    def __init__(self, args, kwargs):  # noqa: D107
        self.args = list(args)
        self.kwargs = dict(kwargs)

    def get(self, index, *names, default=None):
        """The argument at position ``index`` or given by one of the names."""
        for name in names:
            if name in self.kwargs:
                return self.kwargs[name]
        if index is not None and index < len(self.args):
            return self.args[index]
        return default

    def has(self, index, *names):
        """Whether the argument was given."""
        return any(n in self.kwargs for n in names) or (
            index is not None and index < len(self.args))


def _text_value(value):
    """A value usable where launch expects text or substitutions."""
    if isinstance(value, tuple):
        return list(value)
    return value


def _conditions(interp, args, node):
    condition = args.get(None, 'condition')
    if condition is None:
        return []
    if isinstance(condition, Condition):
        return [condition]
    return [Condition('unknown', [f'{interp.loc(node)}: condition not '
                                  'understood'])]


def _common(interp, args, node):
    notes = list(interp.uncertain)
    return {'location': interp.loc(node),
            'conditions': _conditions(interp, args, node), 'notes': notes}


def _entities(interp, value, node, active=None):
    if value is None:
        return []
    if isinstance(value, (list, tuple)):
        active = active if active is not None else set()
        if id(value) in active or len(active) > MAX_CODE_NESTING:
            return [UnknownValue(f'{interp.loc(node)}: a list that contains '
                                 'itself')]
        active.add(id(value))
        out = []
        for item in value:
            if isinstance(item, (list, tuple)):
                out.extend(_entities(interp, item, node, active))
            else:
                out.append(item)
        active.discard(id(value))
        return out
    if isinstance(value, LaunchDescription):
        return list(value.entities)
    if isinstance(value, UnknownValue):
        return [value]
    return [UnknownValue(f'{interp.loc(node)}: actions not known '
                         'statically')]


def _launch_description(interp, args, node):
    return LaunchDescription(_entities(
        interp, args.get(0, 'initial_entities'), node))


def _declare(interp, args, node):
    has_default = args.has(1, 'default_value')
    return DeclareLaunchArgument(
        name=args.get(0, 'name'),
        default=_text_value(args.get(1, 'default_value')),
        has_default=has_default, **_common(interp, args, node))


def _set_configuration(interp, args, node):
    return SetLaunchConfiguration(name=args.get(0, 'name'),
                                  value=_text_value(args.get(1, 'value')),
                                  **_common(interp, args, node))


def _remappings(interp, value, node):
    if value is None:
        return []
    items = value if isinstance(value, (list, tuple)) else None
    if items is None:
        return [UnknownValue(f'{interp.loc(node)}: remappings not known '
                             'statically')]
    out = []
    for item in items:
        if isinstance(item, (list, tuple)) and len(item) == 2:
            out.append((_text_value(item[0]), _text_value(item[1])))
        else:
            out.append(UnknownValue(f'{interp.loc(node)}: a remapping not '
                                    'known statically'))
    return out


def _parameters(interp, value, node):
    if value is None:
        return []
    if not isinstance(value, (list, tuple)):
        return [ParamItem('unknown', value=f'{interp.loc(node)}: parameters '
                          'not known statically')]
    out = []
    for item in value:
        if isinstance(item, dict):
            out.append(ParamItem('dict', value=_param_dict(item)))
        elif isinstance(item, _ParameterFile):
            out.append(ParamItem('file', value=item.path,
                                 allow_substs=item.allow_substs))
        elif isinstance(item, (str, list, PathJoinSubstitution,
                               LaunchConfiguration, PackagePath,
                               EnvironmentVariable, PythonExpression,
                               ThisFile)):
            out.append(ParamItem('file', value=_text_value(item)))
        elif isinstance(item, UnknownValue):
            out.append(ParamItem('unknown', value=item.reason))
        else:
            out.append(ParamItem('unknown', value=f'{interp.loc(node)}: a '
                                 'parameter entry not understood'))
    return out


def _param_dict(data):
    pairs = []
    for key, value in data.items():
        if isinstance(key, HashableValue):
            key = _text_value(key.value)
        pairs.append((key, _param_dict(value) if isinstance(value, dict)
                      else value))
    return ParamDict(pairs)


@dataclass
class _ParameterFile:
    path: object
    allow_substs: bool


def _node(interp, args, node, kind='node'):
    def get(*names):
        return _text_value(args.get(None, *names))
    action = Node(
        package=get('package'),
        executable=get('executable', 'node_executable'),
        name=get('name', 'node_name'),
        namespace=get('namespace', 'node_namespace'),
        remaps=_remappings(interp, args.get(None, 'remappings'), node),
        params=_parameters(interp, args.get(None, 'parameters'), node),
        arguments=_list_value(interp, args.get(None, 'arguments'), node),
        ros_arguments=_list_value(interp, args.get(None, 'ros_arguments'),
                                  node),
        kind=kind, **_common(interp, args, node))
    if kind == 'container':
        action.composables = _composables(
            interp, args.get(None, 'composable_node_descriptions'), node)
    return action


def _list_value(interp, value, node):
    if value is None:
        return []
    if isinstance(value, (list, tuple)):
        return [_text_value(v) for v in value]
    return UnknownValue(f'{interp.loc(node)}: arguments not known '
                        'statically')


def _container(interp, args, node):
    return _node(interp, args, node, kind='container')


def _composables(interp, value, node):
    if value is None:
        return []
    if not isinstance(value, (list, tuple)):
        interp.note(node, 'composable node descriptions not known '
                    'statically')
        return []
    out = []
    for item in value:
        if isinstance(item, ComposableNode):
            out.append(item)
        else:
            interp.note(node, 'a composable node description not '
                        'understood')
    return out


def _composable(interp, args, node):
    def get(*names):
        return _text_value(args.get(None, *names))
    return ComposableNode(
        package=get('package'), plugin=get('plugin'),
        name=get('name'), namespace=get('namespace'),
        remaps=_remappings(interp, args.get(None, 'remappings'), node),
        params=_parameters(interp, args.get(None, 'parameters'), node),
        **_common(interp, args, node))


def _load_composables(interp, args, node):
    return LoadComposableNodes(composables=_composables(
        interp, args.get(None, 'composable_node_descriptions'), node),
        **_common(interp, args, node))


def _include(interp, args, node):
    source = args.get(0, 'launch_description_source')
    if isinstance(source, LaunchSource):
        path = source.path
    elif isinstance(source, (str, list, PathJoinSubstitution, PackagePath,
                             LaunchConfiguration, ThisFile)):
        path = _text_value(source)
    else:
        return interp.unknown(node, 'included launch description not known '
                              'statically')
    raw = args.get(1, 'launch_arguments')
    arguments = []
    if isinstance(raw, dict):
        raw = list(raw.items())
    if raw is not None:
        if not isinstance(raw, (list, tuple)):
            interp.note(node, 'include arguments not known statically')
        else:
            for pair in raw:
                if isinstance(pair, (list, tuple)) and len(pair) == 2:
                    key = pair[0].value if isinstance(
                        pair[0], HashableValue) else pair[0]
                    arguments.append((_text_value(key),
                                      _text_value(pair[1])))
                else:
                    interp.note(node, 'an include argument not understood')
    return IncludeLaunchDescription(path=path, arguments=arguments,
                                    **_common(interp, args, node))


def _source_of(interp, args, node):
    return LaunchSource(_text_value(args.get(0, 'launch_file_path')))


def _group(interp, args, node):
    configurations = []
    raw = args.get(None, 'launch_configurations')
    if isinstance(raw, dict):
        configurations = [
            (k.value if isinstance(k, HashableValue) else k, v)
            for k, v in raw.items()]
    scoped = args.get(1, 'scoped', default=True)
    forwarding = args.get(2, 'forwarding', default=True)
    return GroupAction(actions=_entities(interp, args.get(0, 'actions'), node),
                       scoped=scoped if isinstance(scoped, bool) else True,
                       forwarding=forwarding is not False,
                       configurations=configurations,
                       **_common(interp, args, node))


def _timer(interp, args, node):
    return GroupAction(actions=_entities(interp, args.get(1, 'actions'), node),
                       scoped=False, **_common(interp, args, node))


def _push_namespace(interp, args, node):
    return PushROSNamespace(namespace=_text_value(args.get(0, 'namespace')),
                            **_common(interp, args, node))


def _set_remap(interp, args, node):
    return SetRemap(source=_text_value(args.get(0, 'src')),
                    target=_text_value(args.get(1, 'dst')),
                    **_common(interp, args, node))


def _set_parameter(interp, args, node):
    return SetParameter(name=_text_value(args.get(0, 'name')),
                        value=args.get(1, 'value'),
                        **_common(interp, args, node))


def _set_env(interp, args, node):
    return SetEnv(name=_text_value(args.get(0, 'name')),
                  value=_text_value(args.get(1, 'value', default='')),
                  **_common(interp, args, node))


def _unset_env(interp, args, node):
    return SetEnv(name=_text_value(args.get(0, 'name')), value=None,
                  **_common(interp, args, node))


def _opaque(what):
    def build(interp, args, node):
        return Opaque(note=f'{what}; not analysed',
                      **_common(interp, args, node))
    return build


def _ignored(interp, args, node):
    return Ignored(location=interp.loc(node))


def _event_handler(keyword, what):
    def build(interp, args, node):
        value = args.get(None, keyword)
        if isinstance(value, Function) or value is None:
            return EventHandler([UnknownValue(
                f'{interp.loc(node)}: actions of {what} not known '
                'statically')], what)
        return EventHandler(_entities(interp, value, node), what)
    return build


def _register_event_handler(interp, args, node):
    handler = args.get(0, 'event_handler')
    if not isinstance(handler, EventHandler):
        return interp.unknown(node, 'event handler not understood')
    common = _common(interp, args, node)
    common['notes'] = common['notes'] + [
        f'{interp.loc(node)}: started by an event handler ({handler.what})']
    return GroupAction(actions=handler.actions, scoped=False, **common)


def _launch_configuration(interp, args, node):
    return LaunchConfiguration(_text_value(args.get(0, 'variable_name')),
                               _text_value(args.get(1, 'default')))


def _text_substitution(interp, args, node):
    text = args.get(0, 'text', default='')
    return text if isinstance(text, str) else _text_value(text)


def _path_join(interp, args, node):
    parts = args.get(0, 'substitutions')
    if not isinstance(parts, (list, tuple)):
        return interp.unknown(node, 'PathJoinSubstitution of a value not '
                              'known statically')
    return PathJoinSubstitution([_text_value(p) for p in parts])


def _package_path(kind):
    def build(interp, args, node):
        return PackagePath(_text_value(args.get(0, 'package')), kind)
    return build


def _package_directory(kind):
    def build(interp, args, node):
        package = args.get(0, 'package_name')
        if not isinstance(package, str):
            return interp.unknown(node, 'package name not known statically')
        try:
            return interp.loader.find_package(package, kind)
        except Unresolved as e:
            return interp.unknown(node, str(e))
    return build


def _environment_variable(interp, args, node):
    return EnvironmentVariable(_text_value(args.get(0, 'name')),
                               _text_value(args.get(1, 'default_value')))


def _python_expression(interp, args, node):
    value = args.get(0, 'expression')
    return PythonExpression(list(value) if isinstance(value, (list, tuple))
                            else [value])


def _this_file(directory):
    def build(interp, args, node):
        return ThisFile(directory)
    return build


def _not_static(what):
    def build(interp, args, node):
        return interp.unknown(node, f'{what} is only known at run time')
    return build


def _anon_name(interp, args, node):
    name = args.get(0, 'name')
    if not isinstance(name, str):
        return interp.unknown(node, 'AnonName of a value not known')
    return UnknownValue(f'{interp.loc(node)}: AnonName({name!r}) is a '
                        'unique name chosen at run time')


def _bool_sub(op):
    def build(interp, args, node):
        return BoolOp(op, [_text_value(a) for a in args.args] +
                      [_text_value(v) for v in args.kwargs.values()])
    return build


def _condition(kind):
    def build(interp, args, node):
        return Condition(
            kind, [_text_value(args.get(0, 'predicate_expression'))])
    return build


def _config_equals(kind):
    def build(interp, args, node):
        return Condition(kind, [
            _text_value(args.get(0, 'launch_configuration_name')),
            _text_value(args.get(1, 'expected_value'))])
    return build


def _parameter_file(interp, args, node):
    allow = args.get(1, 'allow_substs', default=False)
    return _ParameterFile(_text_value(args.get(0, 'param_file')),
                          allow is True)


def _parameter_value(interp, args, node):
    value = args.get(0, 'value')
    value_type = args.get(None, 'value_type')
    if isinstance(value_type, Ref) and value_type.qualname == \
            'builtins.str':
        return TypedValue(_text_value(value))
    return _text_value(value)


LAUNCH_API = {
    'LaunchDescription': _launch_description,
    'DeclareLaunchArgument': _declare,
    'SetLaunchConfiguration': _set_configuration,
    'Node': _node,
    'LifecycleNode': _node,
    'ComposableNodeContainer': _container,
    'ComposableNode': _composable,
    'LoadComposableNodes': _load_composables,
    'IncludeLaunchDescription': _include,
    'PythonLaunchDescriptionSource': _source_of,
    'XMLLaunchDescriptionSource': _source_of,
    'YAMLLaunchDescriptionSource': _source_of,
    'AnyLaunchDescriptionSource': _source_of,
    'FrontendLaunchDescriptionSource': _source_of,
    'GroupAction': _group,
    'TimerAction': _timer,
    'PushRosNamespace': _push_namespace,
    'PushROSNamespace': _push_namespace,
    'SetRemap': _set_remap,
    'SetParameter': _set_parameter,
    'SetEnvironmentVariable': _set_env,
    'UnsetEnvironmentVariable': _unset_env,
    'ExecuteProcess': _opaque('ExecuteProcess runs a process that is not a '
                              'ROS node description'),
    'OpaqueFunction': _opaque('OpaqueFunction runs Python code at launch '
                              'time'),
    'SetParametersFromFile': _opaque('SetParametersFromFile'),
    'LogInfo': _ignored,
    'EmitEvent': _ignored,
    'Shutdown': _ignored,
    'RegisterEventHandler': _register_event_handler,
    'OnProcessStart': _event_handler('on_start', 'OnProcessStart'),
    'OnProcessExit': _event_handler('on_exit', 'OnProcessExit'),
    'OnExecutionComplete': _event_handler('on_completion',
                                          'OnExecutionComplete'),
    'OnShutdown': _event_handler('on_shutdown', 'OnShutdown'),
    'LaunchConfiguration': _launch_configuration,
    'TextSubstitution': _text_substitution,
    'PathJoinSubstitution': _path_join,
    'FindPackageShare': _package_path('share'),
    'FindPackagePrefix': _package_path('prefix'),
    'get_package_share_directory': _package_directory('share'),
    'get_package_prefix': _package_directory('prefix'),
    'EnvironmentVariable': _environment_variable,
    'PythonExpression': _python_expression,
    'ThisLaunchFileDir': _this_file(True),
    'ThisLaunchFile': _this_file(False),
    'Command': _not_static('the output of Command'),
    'FindExecutable': _not_static('FindExecutable'),
    'ExecutableInPackage': _not_static('ExecutableInPackage'),
    'AnonName': _anon_name,
    'NotSubstitution': _bool_sub('not'),
    'AndSubstitution': _bool_sub('and'),
    'OrSubstitution': _bool_sub('or'),
    'EqualsSubstitution': _bool_sub('equals'),
    'NotEqualsSubstitution': _bool_sub('not_equals'),
    'IfElseSubstitution': _bool_sub('if_else'),
    'IfCondition': _condition('if'),
    'UnlessCondition': _condition('unless'),
    'LaunchConfigurationEquals': _config_equals('equals'),
    'LaunchConfigurationNotEquals': _config_equals('not_equals'),
    'ParameterFile': _parameter_file,
    'ParameterValue': _parameter_value,
}
