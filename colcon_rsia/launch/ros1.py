# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""ROS 1 (roslaunch) XML launch files, read statically."""

import bisect
from dataclasses import dataclass
from dataclasses import field
import itertools
import os
from typing import Dict
from typing import List
from typing import Optional

from colcon_rsia.launch.common import argument_text
from colcon_rsia.launch.common import check_value
from colcon_rsia.launch.common import flatten
from colcon_rsia.launch.common import fqn
from colcon_rsia.launch.common import join_ns
from colcon_rsia.launch.common import load_yaml
from colcon_rsia.launch.common import location
from colcon_rsia.launch.common import MAX_NESTING
from colcon_rsia.launch.common import parse_bool
from colcon_rsia.launch.common import parse_xml
from colcon_rsia.launch.common import resolve_path
from colcon_rsia.launch.common import UnknownArg
from colcon_rsia.launch.handlers import HandlerTable
from colcon_rsia.launch.model import LaunchError
from colcon_rsia.launch.model import NodeInstance
from colcon_rsia.launch.notes import shorten
from colcon_rsia.launch.notes import unique
from colcon_rsia.launch.substitutions import Resolver
from colcon_rsia.launch.substitutions import Unresolved
import yaml

# element -> the method of Ros1Reader reading it, registered by
# `@_ELEMENTS.handles(tag, ...)`
_ELEMENTS = HandlerTable('launch element')


@dataclass
class _File:
    path: str
    overrides: Dict[str, object]   # values given from outside (CLI/include)
    explicit: List[str]            # overrides that must be declared
    declared: set = field(default_factory=set)


@dataclass
class _Scope:
    file: _File
    args: Dict[str, object]
    ns: Optional[str]
    remaps: list
    notes: list

    def child(self, *, ns=None, notes=()):
        return _Scope(self.file, dict(self.args), self.ns if ns is None
                      else ns, list(self.remaps), self.notes + list(notes))


class Ros1Reader:
    """Reads a ROS 1 launch file and the files it includes."""

    def __init__(self, loader):  # noqa: D107
        self.loader = loader
        self.global_params = {}  # absolute parameter name -> value
        self.instances = []      # (instance, own params) of ROS 1 nodes

    # entry points

    def read_top(self, path, root):
        """Read the top-level file with the command-line arguments."""
        file = _File(path, dict(self.loader.arguments), [])
        scope = _Scope(file, {}, '/', [], [])
        self._file(root, scope, top=True, depth=0)
        self.finish()

    def read_included(self, path, root, *, args, ns, remaps, notes,
                      explicit, depth):
        """Read an included file."""
        file = _File(path, dict(args), list(explicit))
        scope = _Scope(file, {}, ns, list(remaps), list(notes))
        self._file(root, scope, top=False, depth=depth)

    def finish(self):
        """Give each node the global parameters under its private name."""
        self.loader.result.global_params.update(self.global_params)
        keys = sorted(self.global_params)
        for instance, own in self.instances:
            name = fqn(instance.namespace, instance.name)
            params = {}
            if name is not None:
                prefix = name.rstrip('/') + '/'
                start = bisect.bisect_left(keys, prefix)
                for key in itertools.islice(keys, start, None):
                    if not key.startswith(prefix):
                        break
                    params[key[len(prefix):]] = self.global_params[key]
            params.update(own)
            instance.params.clear()
            instance.params.update(params)

    # structure

    def _file(self, root, scope, *, top, depth):
        path = scope.file.path
        if root.tag != 'launch':
            message = f'{path}: the root element is <{root.tag}>, not <launch>'
            if top:
                raise LaunchError(message + '.')
            self.loader.note(message + '; not read')
            return
        self._children(root, scope, depth)
        for name in scope.file.explicit:
            if name not in scope.file.declared:
                self.loader.note(
                    f'{path}: argument {name} is passed by the include but '
                    'not declared by the file')

    def _children(self, elem, scope, depth):
        if depth > MAX_NESTING:
            self.loader.note(
                f'{location(scope.file.path, elem.line)}: elements nested '
                f'deeper than {MAX_NESTING} levels are not read')
            return
        for child in elem.children:
            self._element(child, scope, depth + 1)

    def _resolver(self, scope, notes, declaring=None):
        def lookup(name):
            return argument_text(scope.args, name, declaring=declaring,
                                 missing='is not declared')
        return Resolver(
            dialect='ros1', lookup_arg=lookup, environ=self.loader.environ,
            find_package=self.loader.find_package,
            current_file=scope.file.path, notes=notes)

    def _loc(self, scope, elem):
        return location(scope.file.path, elem.line)

    def _condition(self, elem, scope):
        """True, False, or a note when the condition is not known."""
        resolver = self._resolver(scope, [])
        for attr in ('if', 'unless'):
            if attr not in elem.attrs:
                continue
            text = elem.attrs[attr]
            try:
                value = parse_bool(resolver.substitute(text), attr)
            except Unresolved as e:
                return (f'{self._loc(scope, elem)}: <{elem.tag}> only when '
                        f'{attr}="{shorten(text)}", not known statically '
                        f'({e})')
            if value != (attr == 'if'):
                return False
        return True

    def _element(self, elem, scope, depth):
        condition = self._condition(elem, scope)
        if condition is False:
            return
        uncertain = [] if condition is True else [condition]
        handler = _ELEMENTS.get(elem.tag)
        if handler is None:
            self.loader.note(f'{self._loc(scope, elem)}: unknown element '
                             f'<{shorten(elem.tag, 40)}> ignored')
            return
        handler(self, elem, scope, depth, uncertain)

    @_ELEMENTS.handles('machine', 'env', 'master', 'test')
    def _ignored(self, elem, scope, depth, uncertain):
        """An element that starts nothing and changes nothing we need."""

    @_ELEMENTS.handles('arg')
    def _arg(self, elem, scope, depth, uncertain):
        attrs = elem.attrs
        name = attrs.get('name')
        where = self._loc(scope, elem)
        if not name:
            self.loader.note(f'{where}: <arg> without a name ignored')
            return
        scope.file.declared.add(name)
        file = scope.file
        if uncertain:
            scope.args[name] = UnknownArg(uncertain[0])
            return
        notes = []
        resolver = self._resolver(scope, notes, declaring=name)
        if 'value' in attrs:
            if name in file.overrides and name in file.explicit:
                self.loader.note(
                    f'{where}: argument {name} has a fixed value; the value '
                    'passed to it is ignored')
            text = attrs['value']
        elif name in file.overrides:
            value = file.overrides[name]
            scope.args[name] = value
            return
        elif 'default' in attrs:
            text = attrs['default']
        else:
            scope.args[name] = UnknownArg(
                f'required argument {name} is not given')
            return
        try:
            scope.args[name] = resolver.substitute(text)
        except Unresolved as e:
            scope.args[name] = UnknownArg(str(e))
            self.loader.note(f'{where}: argument {name}: {e}')

    @_ELEMENTS.handles('group')
    def _group(self, elem, scope, depth, uncertain):
        child = scope.child(notes=uncertain)
        if 'ns' in elem.attrs:
            notes = []
            try:
                text = self._resolver(scope, notes).substitute(
                    elem.attrs['ns'])
                child.ns = join_ns(scope.ns, text)
            except Unresolved as e:
                child.ns = None
                child.notes.append(
                    f'{self._loc(scope, elem)}: group namespace not known '
                    f'statically ({e})')
            child.notes.extend(notes)
        self._children(elem, child, depth)

    @_ELEMENTS.handles('remap')
    def _remap(self, elem, scope, depth, uncertain, target=None):
        where = self._loc(scope, elem)
        # a launch- or group-level remap applies to the nodes after it
        notes = scope.notes if target is None else target.notes
        remaps = scope.remaps if target is None else target.remaps
        if 'from' not in elem.attrs or 'to' not in elem.attrs:
            self.loader.note(f'{where}: <remap> needs from and to; ignored')
            return
        resolver = self._resolver(scope, notes)
        try:
            source = resolver.substitute(elem.attrs['from'])
            dest = resolver.substitute(elem.attrs['to'])
        except Unresolved as e:
            notes.append(f'{where}: remap not known statically ({e})')
            return
        remaps.append((source, dest))
        if uncertain:
            notes.append(f'{where}: remap {source} -> {dest} applies only '
                         'under a condition not known statically')

    @_ELEMENTS.handles('include')
    def _include(self, elem, scope, depth, uncertain):
        where = self._loc(scope, elem)
        notes = list(uncertain)
        resolver = self._resolver(scope, notes)
        if 'file' not in elem.attrs:
            self.loader.note(f'{where}: <include> without a file ignored')
            return
        try:
            path = resolve_path(resolver.substitute(elem.attrs['file']),
                                scope.file.path)
        except Unresolved as e:
            self.loader.note(f'{where}: included file not known statically '
                             f'({e}); not read')
            return
        ns = scope.ns
        if 'ns' in elem.attrs:
            try:
                ns = join_ns(scope.ns, resolver.substitute(elem.attrs['ns']))
            except Unresolved as e:
                ns = None
                notes.append(f'{where}: include namespace not known '
                             f'statically ({e})')
        args = {}
        try:
            pass_all = parse_bool(
                resolver.substitute(elem.attrs.get('pass_all_args', 'false')),
                'pass_all_args')
        except Unresolved as e:
            self.loader.note(f'{where}: {e}')
            pass_all = False
        if pass_all:
            args.update(scope.args)
        explicit = []
        for child in elem.children:
            if child.tag != 'arg':
                continue
            condition = self._condition(child, scope)
            if condition is False:
                continue
            name = child.attrs.get('name')
            if not name:
                continue
            explicit.append(name)
            text = child.attrs.get('value', child.attrs.get('default'))
            if condition is not True:
                args[name] = UnknownArg(condition)
            elif text is None:
                args[name] = UnknownArg(f'no value passed for {name}')
            else:
                try:
                    args[name] = resolver.substitute(text)
                except Unresolved as e:
                    args[name] = UnknownArg(str(e))
        self.include_file(path, where, args=args, ns=ns, remaps=scope.remaps,
                          notes=scope.notes + notes, explicit=explicit,
                          depth=depth)

    def include_file(self, path, where, *, args, ns, remaps, notes,
                     explicit, depth):
        """Read an included launch file of any kind (ROS 1 context)."""
        if not self.loader.enter_include(path, where):
            return
        try:
            if path.endswith('.py') or path.endswith(('.yaml', '.yml')):
                self.loader.note(
                    f'{where}: {path} is a ROS 2 launch file; not included '
                    'from a ROS 1 launch file')
                return
            root = parse_xml(self.loader.read_text(path), path)
            self.read_included(path, root, args=args, ns=ns, remaps=remaps,
                               notes=notes, explicit=explicit, depth=depth)
        finally:
            self.loader.leave_include()

    # parameters

    @_ELEMENTS.handles('param')
    def _param(self, elem, scope, depth, uncertain, node=None):
        where = self._loc(scope, elem)
        notes = node.notes if node is not None else []
        name = elem.attrs.get('name')
        if not name:
            self._param_note(node, f'{where}: <param> without a name ignored')
            return
        resolver = self._resolver(scope, notes)
        try:
            name = resolver.substitute(name)
            value = self._param_value(elem, resolver, where)
        except Unresolved as e:
            self._param_note(node, f'{where}: parameter {name} not known '
                                   f'statically ({e})')
            return
        if uncertain:
            self._param_note(node, f'{where}: parameter {name} is set only '
                                   'under a condition not known statically')
        self._set_param(name, value, scope, node, where, separator='/')

    def _param_note(self, node, note):
        if node is not None:
            node.notes.append(note)
        else:
            self.loader.note(note)

    def _param_value(self, elem, resolver, where):
        attrs = elem.attrs
        if 'value' in attrs:
            return _typed(resolver.substitute(attrs['value']),
                          attrs.get('type'))
        if 'textfile' in attrs:
            path = resolve_path(resolver.substitute(attrs['textfile']),
                                resolver.current_file)
            try:
                return self.loader.read_text(path)
            except LaunchError as e:
                raise Unresolved(str(e).rstrip('.'))
        if 'command' in attrs:
            raise Unresolved('its value is the output of a command')
        if 'binfile' in attrs:
            raise Unresolved('its value is a binary file')
        raise Unresolved('it has no value')

    def _set_param(self, name, value, scope, node, where, *, separator):
        """Set a parameter (a dict sets a tree) for a node or globally."""
        if node is not None:
            if name.startswith('/'):
                base = None
            else:
                base = name[1:] if name.startswith('~') else name
            if base is not None:
                flat = flatten(value, base.strip('/'), '/', {}, where) \
                    if isinstance(value, dict) else {base.strip('/'): value}
                node.params.update(flat)
                return
            absolute = name
        else:
            if name.startswith('~'):
                self.loader.note(f'{where}: private parameter {name} outside '
                                 'a node ignored')
                return
            if scope.ns is None and not name.startswith('/'):
                self.loader.note(f'{where}: parameter {name} in a namespace '
                                 'not known statically ignored')
                return
            absolute = join_ns(scope.ns, name)
        flat = flatten(value, absolute, '/', {}, where) \
            if isinstance(value, dict) else {absolute: value}
        for key, item in flat.items():
            self.global_params[join_ns('/', key)] = item

    @_ELEMENTS.handles('rosparam')
    def _rosparam(self, elem, scope, depth, uncertain, node=None):
        where = self._loc(scope, elem)
        attrs = elem.attrs
        notes = node.notes if node is not None else []
        resolver = self._resolver(scope, notes)
        command = attrs.get('command', 'load')
        if command == 'dump':
            return
        if command != 'load':
            self._param_note(node, f'{where}: <rosparam command="'
                                   f'{shorten(command)}"> not applied')
            return
        try:
            subst = parse_bool(resolver.substitute(
                attrs.get('subst_value', 'false')), 'subst_value')
            if 'file' in attrs:
                path = resolve_path(resolver.substitute(attrs['file']),
                                    scope.file.path)
                if not os.path.isfile(path):
                    raise Unresolved(f'parameter file {path} not found')
                source = path
                text = self.loader.read_text(path)
            else:
                source = where
                text = elem.text
            if subst:
                text = resolver.substitute(text)
            data = check_value(load_yaml(text, source), source)
            ns = resolver.substitute(attrs.get('ns', ''))
            param = resolver.substitute(attrs.get('param', ''))
        except Unresolved as e:
            self._param_note(node, f'{where}: <rosparam> not loaded ({e})')
            return
        if uncertain:
            self._param_note(node, f'{where}: <rosparam> is loaded only '
                                   'under a condition not known statically')
        if data is None:
            return
        if param:
            name = f'{ns}/{param}' if ns else param
            self._set_param(name, data, scope, node, where, separator='/')
            return
        if not isinstance(data, dict):
            self._param_note(node, f'{where}: <rosparam> without param= '
                                   'needs a dictionary; not loaded')
            return
        flat = flatten(data, '', '/', {}, source)
        for key, value in flat.items():
            name = f'{ns}/{key}' if ns else key
            self._set_param(name, value, scope, node, where, separator='/')

    # nodes

    @_ELEMENTS.handles('node')
    def _node(self, elem, scope, depth, uncertain):
        attrs = elem.attrs
        where = self._loc(scope, elem)
        notes = list(scope.notes) + list(uncertain)
        resolver = self._resolver(scope, notes)

        def attr(key):
            if key not in attrs:
                return None
            try:
                return resolver.substitute(attrs[key])
            except Unresolved as e:
                notes.append(f'{where}: {key} not known statically ({e})')
                return None

        package = attr('pkg')
        executable = attr('type')
        name = attr('name')
        if 'name' not in attrs:
            notes.append(f'{where}: <node> without a name')
        namespace = scope.ns
        if 'ns' in attrs:
            ns_text = attr('ns')
            namespace = None if ns_text is None else join_ns(scope.ns,
                                                             ns_text)
        args = attr('args')
        kind = 'node'
        arg_tokens = []
        if package == 'nodelet' and executable == 'nodelet':
            if args is None:
                notes.append(f'{where}: nodelet arguments '
                             + ('not known statically' if 'args' in attrs
                                else 'missing') + '; its role is unknown')
            else:
                tokens = args.split()
                verb = tokens[0] if tokens else ''
                if verb == 'manager':
                    kind = 'nodelet_manager'
                    arg_tokens = tokens[1:]
                elif verb in ('load', 'standalone') and len(tokens) >= 2:
                    kind = 'nodelet'
                    executable = tokens[1]
                    package, sep, _ = tokens[1].partition('/')
                    if not sep or not package:
                        package = None
                        notes.append(f'{where}: nodelet plugin '
                                     f'{tokens[1]} has no package part')
                    arg_tokens = tokens[3:] if verb == 'load' else tokens[2:]
                elif verb == 'unload':
                    return
                else:
                    notes.append(f'{where}: nodelet arguments '
                                 f"'{shorten(args)}' not understood")
        elif args:
            arg_tokens = args.split()
        instance = NodeInstance(
            package=package, executable=executable, name=name,
            namespace=namespace, remaps=list(scope.remaps), params={},
            kind=kind, location=where, unresolved=notes)
        holder = _NodeHolder(instance.remaps, {}, notes)
        for child in elem.children:
            condition = self._condition(child, scope)
            if condition is False:
                continue
            child_uncertain = [] if condition is True else [condition]
            if child.tag == 'remap':
                self._remap(child, scope, depth, child_uncertain,
                            target=holder)
            elif child.tag == 'param':
                self._param(child, scope, depth, child_uncertain,
                            node=holder)
            elif child.tag == 'rosparam':
                self._rosparam(child, scope, depth, child_uncertain,
                               node=holder)
            elif child.tag != 'env':
                notes.append(f'{self._loc(scope, child)}: unknown element '
                             f'<{shorten(child.tag, 40)}> in <node> ignored')
        _command_line(arg_tokens, holder)
        instance.args = [t for t in arg_tokens if ':=' not in t]
        notes[:] = unique(notes)
        self.loader.result.instances.append(instance)
        self.instances.append((instance, holder.params))


@dataclass
class _NodeHolder:
    remaps: list
    params: dict
    notes: list


def _command_line(tokens, holder):
    """Remaps (``a:=b``) and private parameters (``_p:=v``) in node args."""
    for token in tokens:
        source, sep, target = token.partition(':=')
        if not sep or not source:
            continue
        if source.startswith('__'):
            continue
        if source.startswith('_'):
            holder.params[source[1:]] = _typed(target, None)
        else:
            holder.remaps.append((source, target))


def _typed(text, type_name):
    """A ROS 1 parameter value from its text and optional type."""
    kind = (type_name or '').strip().lower()
    if kind in ('str', 'string'):
        return text
    if kind == 'int':
        try:
            return int(text.strip())
        except ValueError:
            raise Unresolved(f"'{shorten(text)}' is not an int")
    if kind == 'double':
        try:
            return float(text.strip())
        except ValueError:
            raise Unresolved(f"'{shorten(text)}' is not a double")
    if kind in ('bool', 'boolean'):
        return parse_bool(text, 'bool parameter')
    if kind == 'yaml':
        try:
            return check_value(yaml.safe_load(text), 'yaml parameter')
        except (yaml.YAMLError, RecursionError, LaunchError):
            raise Unresolved('its YAML value is malformed or too large')
    if kind:
        raise Unresolved(f"unknown parameter type '{shorten(kind)}'")
    stripped = text.strip()
    for convert in (int, float):
        try:
            return convert(stripped)
        except ValueError:
            pass
    if stripped.lower() in ('true', 'false'):
        return stripped.lower() == 'true'
    return text
