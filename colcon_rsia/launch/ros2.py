# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""ROS 2 XML and YAML launch files -> the actions of the launch model.

:func:`read_xml_launch` and :func:`read_yaml_launch` turn a file's
elements into the actions and values of :mod:`colcon_rsia.launch.ir`
(``$(...)`` parsed, not resolved); the executor
(:mod:`colcon_rsia.launch.ros2_executor`) runs them.
"""

import re

from colcon_rsia.launch.common import check_value
from colcon_rsia.launch.common import Elem
from colcon_rsia.launch.common import load_yaml
from colcon_rsia.launch.common import location
from colcon_rsia.launch.common import MAX_NESTING
from colcon_rsia.launch.common import parse_xml
from colcon_rsia.launch.common import typed_value
from colcon_rsia.launch.handlers import HandlerTable
from colcon_rsia.launch.ir import ComposableNode
from colcon_rsia.launch.ir import Condition
from colcon_rsia.launch.ir import DeclareLaunchArgument
from colcon_rsia.launch.ir import GroupAction
from colcon_rsia.launch.ir import IncludeLaunchDescription
from colcon_rsia.launch.ir import LoadComposableNodes
from colcon_rsia.launch.ir import Node
from colcon_rsia.launch.ir import Opaque
from colcon_rsia.launch.ir import ParamItem
from colcon_rsia.launch.ir import PushROSNamespace
from colcon_rsia.launch.ir import SetEnv
from colcon_rsia.launch.ir import SetLaunchConfiguration
from colcon_rsia.launch.ir import SetParameter
from colcon_rsia.launch.ir import SetRemap
from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.model import LaunchError
from colcon_rsia.launch.notes import shorten
from colcon_rsia.launch.substitutions import parse
from colcon_rsia.launch.substitutions import Unresolved


def read_xml_launch(path, text, loader, root=None):
    """The actions of a ROS 2 XML launch file.

    :param root: the file's parsed XML, when the caller has it already
    :raises LaunchError: when the file is not XML or its root is not
      ``<launch>``
    """
    if root is None:
        root = parse_xml(text, path)
    if root.tag != 'launch':
        raise LaunchError(
            f'{path}: the root element is <{shorten(root.tag, 40)}>, '
            'not <launch>.')
    return build_actions(root.children, path, loader)


def read_yaml_launch(path, text, loader, root=None):
    """The actions of a ROS 2 YAML launch file.

    :param root: not used (an XML reader's argument; every reader takes
      the same)
    :raises LaunchError: when the file is not a YAML launch file
    """
    try:
        data = load_yaml(text, path)
    except Unresolved as e:
        raise LaunchError(f'{str(e).rstrip(".")}.')
    elems = yaml_entities(data, path, text)
    return build_actions(elems, path, loader)


def build_actions(elems, path, loader):
    """ROS 2 actions of XML or YAML launch elements."""
    builder = _Builder(path, loader)
    return builder.actions(elems, 0)


def _sv(value, where=''):
    """A substitution value of an attribute."""
    if value is None:
        return None
    if isinstance(value, bool):
        return 'true' if value else 'false'
    if isinstance(value, (int, float)):
        return str(value)
    if isinstance(value, str):
        if '$(' not in value:
            return value
        try:
            return parse(value, quotes=True)
        except Unresolved as e:
            return UnknownValue(f'{e}')
    return UnknownValue(f'a {type(value).__name__} where text was expected')


# element tag (XML spelling, and YAML's where it differs) -> the _Builder
# method reading it, registered by `@_ELEMENTS.handles(tag, ...)`
_ELEMENTS = HandlerTable('launch element')


class _Builder:

    def __init__(self, path, loader):
        self.path = path
        self.loader = loader

    def loc(self, elem):
        return location(self.path, elem.line)

    def actions(self, elems, depth):
        if depth > MAX_NESTING:
            self.loader.note(f'{self.path}: elements nested deeper than '
                             f'{MAX_NESTING} levels are not read')
            return []
        out = []
        for elem in elems:
            action = self.action(elem, depth)
            if action is not None:
                out.append(action)
        return out

    def conditions(self, elem):
        conditions = []
        for attr in ('if', 'unless'):
            if attr in elem.attrs:
                conditions.append(Condition(attr, [_sv(elem.attrs[attr])]))
        return conditions

    def action(self, elem, depth):
        """The IR action of one element, through the table of its tag."""
        common = {'location': self.loc(elem),
                  'conditions': self.conditions(elem)}
        build = _ELEMENTS.get(elem.tag)
        if build is None:
            return Opaque(note=f'unknown element <{shorten(elem.tag, 40)}> '
                          'ignored', **common)
        return build(self, elem, common, depth)

    # --- one method per element kind, registered in _ELEMENTS --------------

    @_ELEMENTS.handles('arg')
    def _declare_argument(self, elem, common, depth):
        attrs = elem.attrs
        return DeclareLaunchArgument(
            name=_sv(attrs.get('name')), default=_sv(attrs.get('default')),
            has_default='default' in attrs, **common)

    @_ELEMENTS.handles('let')
    def _set_configuration(self, elem, common, depth):
        return SetLaunchConfiguration(
            name=_sv(elem.attrs.get('name')),
            value=_sv(elem.attrs.get('value')), **common)

    @_ELEMENTS.handles('load_composable_node')
    def _load_composable(self, elem, common, depth):
        return LoadComposableNodes(composables=self.composables(elem),
                                   **common)

    @_ELEMENTS.handles('include')
    def _include(self, elem, common, depth):
        arguments = [(_sv(c.attrs.get('name')),
                      _sv(c.attrs.get('value', c.attrs.get('default'))))
                     for c in elem.children if c.tag == 'arg']
        return IncludeLaunchDescription(
            path=_sv(elem.attrs.get('file')), arguments=arguments, **common)

    @_ELEMENTS.handles('group', 'timer')
    def _group(self, elem, common, depth):
        attrs = elem.attrs
        actions = self.actions(elem.children, depth + 1)
        ns = attrs.get('namespace', attrs.get('ns'))
        if ns is not None:
            actions.insert(0, PushROSNamespace(
                namespace=_sv(ns), location=self.loc(elem)))
        # (a timer's actions run later, unscoped)
        scoped = _sv(attrs.get('scoped', 'true')) if elem.tag == 'group' \
            else False
        forwarding = str(attrs.get('forwarding', 'true')).lower() != 'false'
        return GroupAction(actions=actions, scoped=scoped,
                           forwarding=forwarding, **common)

    @_ELEMENTS.handles('push-ros-namespace', 'push_ros_namespace')
    def _push_namespace(self, elem, common, depth):
        return PushROSNamespace(
            namespace=_sv(elem.attrs.get('namespace', elem.attrs.get('ns'))),
            **common)

    @_ELEMENTS.handles('set_remap', 'set-remap')
    def _set_remap(self, elem, common, depth):
        return SetRemap(source=_sv(elem.attrs.get('from')),
                        target=_sv(elem.attrs.get('to')), **common)

    @_ELEMENTS.handles('set_parameter', 'set-parameter')
    def _set_parameter(self, elem, common, depth):
        return SetParameter(name=_sv(elem.attrs.get('name')),
                            value=_param_text(elem.attrs.get('value')),
                            **common)

    @_ELEMENTS.handles('set_env', 'set-env')
    def _set_env(self, elem, common, depth):
        return SetEnv(name=_sv(elem.attrs.get('name')),
                      value=_sv(elem.attrs.get('value', '')), **common)

    @_ELEMENTS.handles('unset_env', 'unset-env')
    def _unset_env(self, elem, common, depth):
        return SetEnv(name=_sv(elem.attrs.get('name')), value=None, **common)

    @_ELEMENTS.handles('log', 'declare_launch_argument_doc')
    def _nothing(self, elem, common, depth):
        return None  # (documentation and logging: no effect on the graph)

    @_ELEMENTS.handles('executable')
    def _executable(self, elem, common, depth):
        return Opaque(note='<executable> runs a process that is not a ROS '
                      'node description; not analysed', **common)

    @_ELEMENTS.handles('node', 'node_container', 'lifecycle_node')
    def node(self, elem, common, depth):
        attrs = elem.attrs
        kind = {'node_container': 'container',
                'lifecycle_node': 'lifecycle'}.get(elem.tag, 'node')
        action = Node(
            package=_sv(attrs.get('pkg', attrs.get('package'))),
            executable=_sv(attrs.get('exec', attrs.get('executable'))),
            name=_sv(attrs.get('name')),
            namespace=_sv(attrs.get('namespace', attrs.get('ns'))),
            arguments=_sv(attrs.get('args', '')) or [],
            ros_arguments=_sv(attrs.get('ros_args', '')) or [],
            kind=kind, **common)
        self.node_children(elem, action)
        if kind == 'container':
            action.composables = self.composables(elem)
        return action

    def node_children(self, elem, action):
        for child in elem.children:
            if child.tag == 'remap':
                action.remaps.append((_sv(child.attrs.get('from')),
                                      _sv(child.attrs.get('to'))))
            elif child.tag == 'param':
                self.param(child, '', action.params, 0)
            elif child.tag in ('env', 'composable_node', 'extra_arg'):
                continue
            else:
                action.notes.append(
                    f'{self.loc(child)}: unknown element '
                    f'<{shorten(child.tag, 40)}> in <{elem.tag}> ignored')

    def param(self, elem, prefix, params, depth):
        attrs = elem.attrs
        if 'from' in attrs:
            allow = str(attrs.get('allow_substs', 'false')).lower() == 'true'
            params.append(ParamItem('file', value=_sv(attrs['from']),
                                    allow_substs=allow))
            return
        name = attrs.get('name')
        if name is None:
            params.append(ParamItem(
                'unknown', value=f'{self.loc(elem)}: <param> without a name'))
            return
        full = f'{prefix}.{name}' if prefix else str(name)
        nested = [c for c in elem.children if c.tag == 'param']
        if nested and depth < MAX_NESTING:
            for child in nested:
                self.param(child, full, params, depth + 1)
            return
        value = attrs.get('value')
        separator = attrs.get('value-sep', attrs.get('value_sep'))
        if isinstance(value, str) and separator:
            value = [typed_value(v) for v in value.split(str(separator))] \
                if '$(' not in value else _sv(value)
            params.append(ParamItem('value', name=full, value=value))
            return
        params.append(ParamItem('value', name=full, value=_param_text(value)))

    def composables(self, elem):
        out = []
        for child in elem.children:
            if child.tag != 'composable_node':
                continue
            attrs = child.attrs
            action = ComposableNode(
                package=_sv(attrs.get('pkg', attrs.get('package'))),
                plugin=_sv(attrs.get('plugin')),
                name=_sv(attrs.get('name')),
                namespace=_sv(attrs.get('namespace', attrs.get('ns'))),
                location=self.loc(child), conditions=self.conditions(child))
            self.node_children(child, action)
            out.append(action)
        return out


def _param_text(value):
    """A parameter value of an XML/YAML attribute."""
    if isinstance(value, str):
        return _sv(value)
    if isinstance(value, list):
        return [_sv(v) if isinstance(v, str) else v for v in value]
    if isinstance(value, dict):
        return UnknownValue('a dictionary is not a parameter value')
    return value


_YAML_ENTITY_LINE = re.compile(r'^[ \t]*-[ \t]+([A-Za-z_][\w-]*)[ \t]*:',
                               re.MULTILINE)


def yaml_entities(data, path, text):
    """The entities of a ROS 2 YAML launch file as :class:`Elem`."""
    if not isinstance(data, dict) or 'launch' not in data:
        raise LaunchError(f'{path}: not a ROS 2 YAML launch file (no '
                          "top-level 'launch' list).")
    check_value(data, path)
    entities = data['launch']
    if entities is None:
        return []
    if not isinstance(entities, list):
        raise LaunchError(f"{path}: 'launch' must be a list of entities.")
    lines = [(text.count('\n', 0, m.start()) + 1, m.group(1))
             for m in _YAML_ENTITY_LINE.finditer(text)]
    converter = _YamlConverter(path, lines)
    return converter.entities(entities, 0)


class _YamlConverter:

    def __init__(self, path, lines):
        self.path = path
        self.lines = lines
        self.next = 0

    def line_of(self, tag):
        for index in range(self.next, len(self.lines)):
            if self.lines[index][1] == tag:
                self.next = index + 1
                return self.lines[index][0]
        return 1

    def entities(self, items, depth):
        out = []
        if depth > MAX_NESTING or not isinstance(items, list):
            return out
        for item in items:
            if not isinstance(item, dict) or len(item) != 1:
                out.append(Elem('invalid-entity', {}, line=1))
                continue
            tag, body = next(iter(item.items()))
            out.append(self.elem(str(tag), body, self.line_of(str(tag)),
                                 depth))
        return out

    def elem(self, tag, body, line, depth):
        elem = Elem(tag, {}, line=line)
        if isinstance(body, list):
            # `group: [...]`: the list is the children (launch_yaml's form)
            elem.children.extend(self.entities(body, depth + 1))
            return elem
        if not isinstance(body, dict):
            return elem
        for key, value in body.items():
            key = str(key)
            if key == 'children':
                elem.children.extend(self.entities(value, depth + 1))
            elif isinstance(value, list) and value and \
                    all(isinstance(v, dict) for v in value) and \
                    depth < MAX_NESTING:
                for v in value:
                    elem.children.append(self.elem(key, v, line, depth + 1))
            else:
                elem.attrs[key] = value
        return elem
