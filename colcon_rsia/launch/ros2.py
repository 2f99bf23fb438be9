# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""ROS 2 launch: one action model, executed statically.

The XML and YAML front ends (here) and the Python front end
(:mod:`colcon_rsia.launch.python_launch`) turn a file into a list of
actions (the model of :mod:`colcon_rsia.launch.ir`);
:class:`Ros2Executor` walks them in launch order with the launch
configurations, pushed namespaces, global remaps and parameters in scope,
and records a :class:`NodeInstance` for every node, container and
component.
"""

from dataclasses import dataclass
import os
import re
from typing import Optional

from colcon_rsia.launch.common import check_value
from colcon_rsia.launch.common import Elem
from colcon_rsia.launch.common import file_kind
from colcon_rsia.launch.common import join_ns
from colcon_rsia.launch.common import load_yaml
from colcon_rsia.launch.common import location
from colcon_rsia.launch.common import MAX_NESTING
from colcon_rsia.launch.common import normalise_ns
from colcon_rsia.launch.common import params_from_sections
from colcon_rsia.launch.common import parse_bool
from colcon_rsia.launch.common import parse_xml
from colcon_rsia.launch.common import resolve_path
from colcon_rsia.launch.common import ros2_param_sections
from colcon_rsia.launch.common import ros_arguments
from colcon_rsia.launch.common import typed_value
from colcon_rsia.launch.common import UnknownArg
from colcon_rsia.launch.ir import Action
from colcon_rsia.launch.ir import BoolOp
from colcon_rsia.launch.ir import ComposableNodeAction
from colcon_rsia.launch.ir import Cond
from colcon_rsia.launch.ir import DeclareArgument
from colcon_rsia.launch.ir import EnvVar
from colcon_rsia.launch.ir import Group
from colcon_rsia.launch.ir import Ignored
from colcon_rsia.launch.ir import Include
from colcon_rsia.launch.ir import LaunchConfig
from colcon_rsia.launch.ir import LoadComposable
from colcon_rsia.launch.ir import NodeAction
from colcon_rsia.launch.ir import Opaque
from colcon_rsia.launch.ir import PackagePath
from colcon_rsia.launch.ir import ParamDict
from colcon_rsia.launch.ir import ParamItem
from colcon_rsia.launch.ir import PathJoin
from colcon_rsia.launch.ir import PushNamespace
from colcon_rsia.launch.ir import PyExpr
from colcon_rsia.launch.ir import SetConfiguration
from colcon_rsia.launch.ir import SetEnv
from colcon_rsia.launch.ir import SetParameter
from colcon_rsia.launch.ir import SetRemap
from colcon_rsia.launch.ir import ThisFile
from colcon_rsia.launch.ir import TypedValue
from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.model import LaunchError
from colcon_rsia.launch.model import NodeInstance
from colcon_rsia.launch.notes import shorten
from colcon_rsia.launch.notes import unique
from colcon_rsia.launch.python_launch import read_python_launch
from colcon_rsia.launch.safe_eval import evaluate
from colcon_rsia.launch.safe_eval import to_text
from colcon_rsia.launch.substitutions import Call
from colcon_rsia.launch.substitutions import Concat
from colcon_rsia.launch.substitutions import MAX_VALUE_LENGTH
from colcon_rsia.launch.substitutions import parse
from colcon_rsia.launch.substitutions import Resolver
from colcon_rsia.launch.substitutions import Text
from colcon_rsia.launch.substitutions import Unresolved

# launch actions executed in one load: real systems have a few thousand;
# actions shared in nested Python lists must not multiply without bound
MAX_ACTIONS = 200000
# parts one value may be made of: a value built by doubling itself in a
# loop must not take exponential time to resolve
MAX_VALUE_PARTS = 100000


# execution


@dataclass
class Ctx:
    """What is in scope while executing actions."""

    file: str
    configs: dict
    ns: Optional[str]
    remaps: list
    params: list      # (name, value) of SetParameter
    environ: dict
    notes: list

    def copy(self):
        """A child scope: changes to it do not reach this one."""
        return Ctx(self.file, dict(self.configs), self.ns, list(self.remaps),
                   list(self.params), dict(self.environ), list(self.notes))


class Ros2Executor:
    """Executes ROS 2 launch actions statically."""

    def __init__(self, loader):  # noqa: D107
        self.loader = loader

    # files

    def run_top(self, path, kind, text, root=None):
        """Read and execute the top-level file."""
        ctx = Ctx(path, dict(self.loader.arguments), '/', [], [],
                  dict(self.loader.environ), [])
        actions = self.actions_of(path, kind, text, root)
        self.execute(actions, ctx, 0)

    def actions_of(self, path, kind, text, root=None):
        """The actions of a ROS 2 launch file of a kind."""
        if kind == 'python':
            return read_python_launch(path, text, self.loader)
        if kind == 'yaml':
            try:
                data = load_yaml(text, path)
            except Unresolved as e:
                raise LaunchError(f'{str(e).rstrip(".")}.')
            elems = yaml_entities(data, path, text)
            return build_actions(elems, path, self.loader)
        if root is None:
            root = parse_xml(text, path)
        if root.tag != 'launch':
            raise LaunchError(
                f'{path}: the root element is <{shorten(root.tag, 40)}>, '
                'not <launch>.')
        return build_actions(root.children, path, self.loader)

    def include(self, action, ctx, depth):
        """Execute an included file in a scope of its own."""
        notes = []
        where = action.location
        try:
            path = self.text(action.path, ctx, notes)
        except Unresolved as e:
            self.loader.note(f'{where}: included file not known statically '
                             f'({e}); not read')
            return
        path = resolve_path(path, ctx.file)
        child = ctx.copy()
        child.notes.extend(notes)
        for name, value in action.arguments:
            try:
                key = self.text(name, ctx, child.notes)
            except Unresolved as e:
                self.loader.note(f'{where}: include argument name not known '
                                 f'({e})')
                continue
            try:
                child.configs[key] = self.text(value, ctx, child.notes)
            except Unresolved as e:
                child.configs[key] = UnknownArg(str(e))
        if not os.path.isfile(path):
            self.loader.note(f'{where}: included file {path} not found')
            return
        if not self.loader.enter_include(path, where):
            return
        try:
            text = self.loader.read_text(path)
            root = None
            if not path.lower().endswith(('.py', '.yaml', '.yml')):
                root = parse_xml(text, path)
            kind = file_kind(path, text, root)
            if kind == 'ros1':
                self.loader.note(f'{where}: {path} is a ROS 1 launch file; '
                                 'not included from a ROS 2 launch file')
                return
            actions = self.actions_of(path, kind, text, root)
            child.file = path
            self.execute(actions, child, depth + 1)
        finally:
            self.loader.leave_include()

    # actions

    def execute(self, actions, ctx, depth):
        """Execute actions in order in a context."""
        if depth > MAX_NESTING:
            self.loader.note(f'{ctx.file}: groups and includes nested deeper '
                             f'than {MAX_NESTING} levels are not read')
            return
        for action in actions:
            self._action(action, ctx, depth)

    def _action(self, action, ctx, depth):
        self.loader.actions += 1
        if self.loader.actions > MAX_ACTIONS:
            if self.loader.actions == MAX_ACTIONS + 1:
                self.loader.note(f'{ctx.file}: more than {MAX_ACTIONS} '
                                 'launch actions; the rest is not read')
            return
        if isinstance(action, (list, tuple)):
            self.execute(list(action), ctx, depth + 1)
            return
        if action is None or isinstance(action, Ignored):
            return
        if not isinstance(action, Action):
            reason = action.reason if isinstance(action, UnknownValue) \
                else f'a {type(action).__name__} value'
            self.loader.note(f'{ctx.file}: a launch description entity is '
                             f'not understood ({reason})')
            return
        condition = self.condition(action, ctx)
        if condition is False:
            return
        uncertain = [] if condition is True else [condition]
        method = getattr(self, '_' + type(action).__name__)
        method(action, ctx, depth, uncertain + action.notes)

    def condition(self, action, ctx):
        """True, False, or a note when not known statically."""
        for cond in action.conditions:
            try:
                value = self._condition_value(cond, ctx)
            except Unresolved as e:
                return (f'{action.location}: started only under a condition '
                        f'not known statically ({e})')
            if not value:
                return False
        return True

    def _condition_value(self, cond, ctx):
        if cond.kind == 'unknown':
            raise Unresolved(cond.operands[0])
        if cond.kind in ('if', 'unless'):
            value = parse_bool(self.text(cond.operands[0], ctx, []),
                               cond.kind)
            return value if cond.kind == 'if' else not value
        name = self.text(cond.operands[0], ctx, [])
        expected = cond.operands[1]
        actual = ctx.configs.get(name)
        if isinstance(actual, UnknownArg):
            raise Unresolved(f"argument '{name}' is not known: "
                             f'{actual.reason}')
        if expected is not None:
            expected = self.text(expected, ctx, [])
        equal = actual == expected
        return equal if cond.kind == 'equals' else not equal

    def _DeclareArgument(self, action, ctx, depth, uncertain):  # noqa: N802
        try:
            name = self.text(action.name, ctx, [])
        except Unresolved as e:
            self.loader.note(f'{action.location}: argument name not known '
                             f'({e})')
            return
        if uncertain:
            if name not in ctx.configs:
                ctx.configs[name] = UnknownArg(uncertain[0])
            return
        if name in ctx.configs:
            return
        if not action.has_default:
            ctx.configs[name] = UnknownArg(
                f'required argument {name} is not given')
            return
        try:
            ctx.configs[name] = self.text(action.default, ctx, [],
                                          declaring=name)
        except Unresolved as e:
            ctx.configs[name] = UnknownArg(str(e))
            self.loader.note(f'{action.location}: argument {name}: {e}')

    def _SetConfiguration(self, action, ctx, depth, uncertain):  # noqa: N802
        try:
            name = self.text(action.name, ctx, [])
        except Unresolved as e:
            self.loader.note(f'{action.location}: configuration name not '
                             f'known ({e})')
            return
        if uncertain:
            ctx.configs[name] = UnknownArg(uncertain[0])
            return
        try:
            ctx.configs[name] = self.text(action.value, ctx, [])
        except Unresolved as e:
            ctx.configs[name] = UnknownArg(str(e))

    def _Group(self, action, ctx, depth, uncertain):  # noqa: N802
        scoped = action.scoped
        if not isinstance(scoped, bool):
            try:
                scoped = parse_bool(self.text(scoped, ctx, []), 'scoped')
            except Unresolved:
                scoped = True
        inner = ctx.copy() if scoped else ctx
        added = [n for n in uncertain if n not in inner.notes]
        inner.notes.extend(added)
        if not action.forwarding and scoped:
            inner.configs = {}
        for name, value in action.configurations:
            try:
                key = self.text(name, ctx, [])
                inner.configs[key] = self.text(value, ctx, [])
            except Unresolved as e:
                self.loader.note(f'{action.location}: group configuration '
                                 f'not known ({e})')
        self.execute(action.actions, inner, depth + 1)
        if not scoped:
            for note in added:
                if note in inner.notes:
                    inner.notes.remove(note)

    def _Include(self, action, ctx, depth, uncertain):  # noqa: N802
        if uncertain:
            ctx = ctx.copy()
            ctx.notes.extend(uncertain)
        self.include(action, ctx, depth)

    def _PushNamespace(self, action, ctx, depth, uncertain):  # noqa: N802
        try:
            ns = self.text(action.namespace, ctx, ctx.notes)
            ctx.ns = join_ns(ctx.ns, ns)
        except Unresolved as e:
            ctx.ns = None
            ctx.notes.append(f'{action.location}: pushed namespace not '
                             f'known statically ({e})')
        if uncertain:
            ctx.notes.extend(uncertain)

    def _SetRemap(self, action, ctx, depth, uncertain):  # noqa: N802
        try:
            pair = (self.text(action.source, ctx, ctx.notes),
                    self.text(action.target, ctx, ctx.notes))
        except Unresolved as e:
            ctx.notes.append(f'{action.location}: remap not known '
                             f'statically ({e})')
            return
        ctx.remaps.append(pair)
        for note in uncertain:
            ctx.notes.append(f'{action.location}: remap {pair[0]} -> '
                             f'{pair[1]} applies only when: {note}')

    def _SetParameter(self, action, ctx, depth, uncertain):  # noqa: N802
        try:
            name = self.text(action.name, ctx, ctx.notes)
            value = self.param_value(action.value, ctx, ctx.notes)
        except Unresolved as e:
            ctx.notes.append(f'{action.location}: global parameter not known '
                             f'statically ({e})')
            return
        ctx.params.append((name, value))
        for note in uncertain:
            ctx.notes.append(f'{action.location}: parameter {name} is set '
                             f'only when: {note}')

    def _SetEnv(self, action, ctx, depth, uncertain):  # noqa: N802
        try:
            name = self.text(action.name, ctx, [])
        except Unresolved:
            return
        if action.value is None:
            ctx.environ.pop(name, None)
            return
        try:
            ctx.environ[name] = self.text(action.value, ctx, [])
        except Unresolved:
            ctx.environ.pop(name, None)

    def _Opaque(self, action, ctx, depth, uncertain):  # noqa: N802
        self.loader.note(f'{action.location}: {action.note}')

    def _LoadComposable(self, action, ctx, depth, uncertain):  # noqa: N802
        for composable in action.composables:
            self._component(composable, ctx, uncertain)

    def _NodeAction(self, action, ctx, depth, uncertain):  # noqa: N802
        notes = unique(ctx.notes + uncertain)
        where = action.location
        package = self._field(action.package, 'package', ctx, notes, where)
        executable = self._field(action.executable, 'executable', ctx,
                                 notes, where)
        name = self._field(action.name, 'name', ctx, notes, where)
        namespace = self._namespace(action.namespace, ctx, notes, where)
        remaps = list(ctx.remaps)
        self._remaps(action.remaps, ctx, remaps, notes, where)
        params = {}
        tokens = self._tokens(action.arguments, ctx, notes, where)
        ros_tokens = self._tokens(action.ros_arguments, ctx, notes, where)
        overrides = ros_arguments(tokens, remaps, params, notes, where,
                                  after_ros_args=False)
        overrides.update(ros_arguments(ros_tokens, remaps, params, notes,
                                       where, after_ros_args=True))
        name = overrides.get('__node', overrides.get('__name', name))
        if '__ns' in overrides:
            namespace = normalise_ns(overrides['__ns'])
        params = self._params(action.params, ctx, name, namespace, notes,
                              where, extra=params)
        kind = 'container' if action.kind == 'container' else 'node'
        if action.kind == 'lifecycle':
            kind = 'node'
        self.loader.result.instances.append(NodeInstance(
            package=package, executable=executable, name=name,
            namespace=namespace, remaps=remaps, params=params, kind=kind,
            location=where, unresolved=unique(notes)))
        for composable in action.composables:
            self._component(composable, ctx, uncertain)

    def _component(self, action, ctx, uncertain):
        condition = self.condition(action, ctx)
        if condition is False:
            return
        notes = unique(ctx.notes + uncertain + action.notes + (
            [] if condition is True else [condition]))
        where = action.location
        package = self._field(action.package, 'package', ctx, notes, where)
        plugin = self._field(action.plugin, 'plugin', ctx, notes, where)
        name = self._field(action.name, 'name', ctx, notes, where)
        namespace = self._namespace(action.namespace, ctx, notes, where)
        remaps = list(ctx.remaps)
        self._remaps(action.remaps, ctx, remaps, notes, where)
        params = self._params(action.params, ctx, name, namespace, notes,
                              where)
        self.loader.result.instances.append(NodeInstance(
            package=package, executable=plugin, name=name,
            namespace=namespace, remaps=remaps, params=params,
            kind='component', location=where, unresolved=unique(notes)))

    # fields

    def _field(self, value, what, ctx, notes, where):
        if value is None:
            return None
        try:
            return self.text(value, ctx, notes)
        except Unresolved as e:
            notes.append(f'{where}: {what} not known statically ({e})')
            return None

    def _namespace(self, value, ctx, notes, where):
        if value is None:
            return ctx.ns
        text = self._field(value, 'namespace', ctx, notes, where)
        if text is None:
            return None
        if text.startswith('/'):
            return normalise_ns(text)
        return join_ns(ctx.ns, text)

    def _remaps(self, pairs, ctx, remaps, notes, where):
        for pair in pairs:
            if isinstance(pair, UnknownValue):
                notes.append(f'{where}: remap not known statically '
                             f'({pair.reason})')
                continue
            try:
                remaps.append((self.text(pair[0], ctx, notes),
                               self.text(pair[1], ctx, notes)))
            except Unresolved as e:
                notes.append(f'{where}: remap not known statically ({e})')

    def _tokens(self, values, ctx, notes, where):
        tokens = []
        if isinstance(values, UnknownValue):
            notes.append(f'{where}: arguments not known statically '
                         f'({values.reason})')
            return []
        if isinstance(values, (str, Text, Concat, Call)):
            try:
                return self.text(values, ctx, notes).split()
            except Unresolved as e:
                notes.append(f'{where}: arguments not known statically '
                             f'({e})')
                return []
        for value in values:
            try:
                tokens.append(self.text(value, ctx, notes))
            except Unresolved as e:
                notes.append(f'{where}: an argument is not known statically '
                             f'({e})')
        return tokens

    def _params(self, items, ctx, name, namespace, notes, where, extra=None):
        out = {}
        for key, value in ctx.params:
            out[key] = value
        node_fqn = None
        if name is not None and namespace is not None:
            node_fqn = normalise_ns(f'{namespace}/{name}')
        for item in items:
            try:
                self._param_item(item, ctx, node_fqn, out, notes, where)
            except Unresolved as e:
                notes.append(f'{where}: parameters not known statically '
                             f'({e})')
        out.update(extra or {})
        return out

    def _param_item(self, item, ctx, node_fqn, out, notes, where):
        if item.kind == 'unknown':
            raise Unresolved(item.value)
        if item.kind == 'value':
            name = self.text(item.name, ctx, notes)
            try:
                out[name] = self.param_value(item.value, ctx, notes)
            except Unresolved as e:
                notes.append(f'{where}: parameter {name} not known '
                             f'statically ({e})')
            return
        if item.kind == 'dict':
            self._param_dict(item.value, '', ctx, out, notes, where, 0)
            return
        path = resolve_path(self.text(item.value, ctx, notes), ctx.file)
        if not os.path.isfile(path):
            raise Unresolved(f'parameter file {path} not found')
        text = self.loader.read_text(path)
        if item.allow_substs:
            text = self.resolver(ctx, notes).substitute(text)
        data = load_yaml(text, path)
        sections = ros2_param_sections(data, path)
        params_from_sections(sections, node_fqn, out, path, notes)

    def _param_dict(self, data, prefix, ctx, out, notes, where, depth):
        if depth > MAX_NESTING:
            raise Unresolved('parameters nested too deeply')
        if isinstance(data, UnknownValue):
            raise Unresolved(data.reason)
        for key, value in data.pairs:
            try:
                name = self.text(key, ctx, notes)
            except Unresolved as e:
                notes.append(f'{where}: a parameter name is not known '
                             f'statically ({e})')
                continue
            full = f'{prefix}.{name}' if prefix else name
            if isinstance(value, ParamDict):
                self._param_dict(value, full, ctx, out, notes, where,
                                 depth + 1)
                continue
            try:
                out[full] = self.param_value(value, ctx, notes)
            except Unresolved as e:
                notes.append(f'{where}: parameter {full} not known '
                             f'statically ({e})')

    def param_value(self, value, ctx, notes):
        """A parameter value: typed as launch_ros types text values."""
        if isinstance(value, TypedValue):
            return self.text(value.value, ctx, notes)
        if value is None or isinstance(value, (bool, int, float)):
            return value
        if isinstance(value, (list, tuple)):
            if any(_is_substitution(v) for v in value):
                return typed_value(self.text(list(value), ctx, notes))
            items = []
            for v in value:
                if isinstance(v, (list, tuple, dict)):
                    raise Unresolved('nested lists are not parameter values')
                items.append(v if isinstance(v, (str, bool, int, float))
                             else self.param_value(v, ctx, notes))
            return items
        if isinstance(value, dict):
            raise Unresolved('a dictionary is not a parameter value')
        return typed_value(self.text(value, ctx, notes))

    # substitutions

    def resolver(self, ctx, notes, declaring=None):
        """A substitution resolver over a context."""
        def lookup(name):
            if name == declaring:
                raise Unresolved(f"argument '{name}' refers to itself")
            if name not in ctx.configs:
                raise Unresolved(f"argument '{name}' is not set")
            value = ctx.configs[name]
            if isinstance(value, UnknownArg):
                raise Unresolved(f"argument '{name}' is not known: "
                                 f'{value.reason}')
            return value
        return Resolver(
            dialect='ros2', lookup_arg=lookup, environ=ctx.environ,
            find_package=self.loader.find_package, current_file=ctx.file,
            notes=notes)

    def text(self, value, ctx, notes, declaring=None):
        """The text of a value (literal, parsed substitution or Python)."""
        resolver = self.resolver(ctx, notes, declaring)
        budget = [MAX_VALUE_PARTS]
        result = self._text(value, ctx, resolver, budget, 0)
        if len(result) > MAX_VALUE_LENGTH:
            raise Unresolved('a substituted value is too long')
        return result

    def _text(self, value, ctx, resolver, budget, depth):
        budget[0] -= 1
        if budget[0] < 0 or depth > 200:
            raise Unresolved('a value is built from too many parts')
        if isinstance(value, str):
            return value
        if isinstance(value, bool):
            return 'true' if value else 'false'
        if isinstance(value, (int, float)):
            return str(value)
        if isinstance(value, (Text, Concat, Call)):
            return resolver.resolve(value)
        if isinstance(value, (list, tuple)):
            parts = []
            size = 0
            for v in value:
                part = self._text(v, ctx, resolver, budget, depth + 1)
                size += len(part)
                if size > MAX_VALUE_LENGTH:
                    raise Unresolved('a substituted value is too long')
                parts.append(part)
            return ''.join(parts)
        if isinstance(value, UnknownValue):
            raise Unresolved(value.reason)
        if isinstance(value, LaunchConfig):
            name = self._text(value.name, ctx, resolver, budget, depth + 1)
            if name not in ctx.configs and value.default is not None:
                return self._text(value.default, ctx, resolver, budget,
                                  depth + 1)
            return resolver.lookup_arg(name)
        if isinstance(value, PackagePath):
            package = self._text(value.package, ctx, resolver, budget,
                                 depth + 1)
            return self.loader.find_package(package, value.kind)
        if isinstance(value, EnvVar):
            name = self._text(value.name, ctx, resolver, budget, depth + 1)
            if name in ctx.environ:
                return ctx.environ[name]
            if value.default is not None:
                return self._text(value.default, ctx, resolver, budget,
                                  depth + 1)
            raise Unresolved(f'environment variable {name} is not set')
        if isinstance(value, PathJoin):
            parts = [self._text(p, ctx, resolver, budget, depth + 1)
                     for p in value.parts]
            return os.path.join(*parts) if parts else ''
        if isinstance(value, PyExpr):
            expression = self._text(value.parts, ctx, resolver, budget,
                                    depth + 1)
            return to_text(evaluate(expression, lookup=resolver.lookup_arg))
        if isinstance(value, ThisFile):
            path = os.path.abspath(ctx.file)
            return os.path.dirname(path) if value.directory else path
        if isinstance(value, BoolOp):
            return self._bool_op(value, ctx, resolver, budget, depth)
        if isinstance(value, TypedValue):
            return self._text(value.value, ctx, resolver, budget, depth + 1)
        raise Unresolved(f'a {type(value).__name__} is not a text value')

    def _bool_op(self, value, ctx, resolver, budget, depth):
        texts = [self._text(v, ctx, resolver, budget, depth + 1)
                 for v in value.operands]
        op = value.op
        if op in ('equals', 'not_equals'):
            if len(texts) != 2:
                raise Unresolved('an equality needs two values')
            equal = texts[0] == texts[1]
            result = equal if op == 'equals' else not equal
        elif op == 'if_else':
            if len(texts) != 3:
                raise Unresolved('IfElseSubstitution needs three values')
            return texts[1] if parse_bool(texts[0], 'condition') \
                else texts[2]
        else:
            bools = [parse_bool(t, op) for t in texts]
            if op == 'not' and len(bools) == 1:
                result = not bools[0]
            elif op == 'and':
                result = all(bools)
            elif op == 'or':
                result = any(bools)
            else:
                raise Unresolved(f'{op} substitution not understood')
        return 'true' if result else 'false'


def _is_substitution(value):
    return isinstance(value, (
        Text, Concat, Call, LaunchConfig, PackagePath, EnvVar, PathJoin,
        PyExpr, ThisFile, BoolOp, UnknownValue))


# XML and YAML front ends


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


_PUSH = ('push-ros-namespace', 'push_ros_namespace')


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
                conditions.append(Cond(attr, [_sv(elem.attrs[attr])]))
        return conditions

    def action(self, elem, depth):
        attrs = elem.attrs
        common = {'location': self.loc(elem),
                  'conditions': self.conditions(elem)}
        tag = elem.tag
        if tag == 'arg':
            has_default = 'default' in attrs
            return DeclareArgument(name=_sv(attrs.get('name')),
                                   default=_sv(attrs.get('default')),
                                   has_default=has_default, **common)
        if tag == 'let':
            return SetConfiguration(name=_sv(attrs.get('name')),
                                    value=_sv(attrs.get('value')), **common)
        if tag in ('node', 'node_container', 'lifecycle_node'):
            return self.node(elem, common, depth)
        if tag == 'load_composable_node':
            return LoadComposable(
                composables=self.composables(elem), **common)
        if tag == 'include':
            arguments = [(_sv(c.attrs.get('name')),
                          _sv(c.attrs.get('value', c.attrs.get('default'))))
                         for c in elem.children if c.tag == 'arg']
            return Include(path=_sv(attrs.get('file')), arguments=arguments,
                           **common)
        if tag in ('group', 'timer'):
            actions = self.actions(elem.children, depth + 1)
            ns = attrs.get('namespace', attrs.get('ns'))
            if ns is not None:
                actions.insert(0, PushNamespace(
                    namespace=_sv(ns), location=self.loc(elem)))
            scoped = _sv(attrs.get('scoped', 'true')) if tag == 'group' \
                else False
            forwarding = str(attrs.get('forwarding', 'true')).lower() != \
                'false'
            return Group(actions=actions, scoped=scoped,
                         forwarding=forwarding, **common)
        if tag in _PUSH:
            return PushNamespace(
                namespace=_sv(attrs.get('namespace', attrs.get('ns'))),
                **common)
        if tag in ('set_remap', 'set-remap'):
            return SetRemap(source=_sv(attrs.get('from')),
                            target=_sv(attrs.get('to')), **common)
        if tag in ('set_parameter', 'set-parameter'):
            return SetParameter(name=_sv(attrs.get('name')),
                                value=_param_text(attrs.get('value')),
                                **common)
        if tag in ('set_env', 'set-env'):
            return SetEnv(name=_sv(attrs.get('name')),
                          value=_sv(attrs.get('value', '')), **common)
        if tag in ('unset_env', 'unset-env'):
            return SetEnv(name=_sv(attrs.get('name')), value=None, **common)
        if tag in ('log', 'declare_launch_argument_doc'):
            return None
        if tag == 'executable':
            return Opaque(note='<executable> runs a process that is not a '
                          'ROS node description; not analysed', **common)
        return Opaque(note=f'unknown element <{shorten(tag, 40)}> ignored',
                      **common)

    def node(self, elem, common, depth):
        attrs = elem.attrs
        kind = {'node_container': 'container',
                'lifecycle_node': 'lifecycle'}.get(elem.tag, 'node')
        action = NodeAction(
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
            action = ComposableNodeAction(
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
