# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The ROS 2 launch executor: actions -> node instances, read never run.

The readers (XML and YAML: :mod:`colcon_rsia.launch.ros2`; Python:
:mod:`colcon_rsia.launch.python_launch`) turn a file into the actions of
:mod:`colcon_rsia.launch.ir`; :class:`Ros2Executor` walks them in launch
order with the launch configurations, pushed namespaces, global remaps and
parameters in scope, and records a :class:`NodeInstance` for every node,
container and component. Values are resolved by
:class:`colcon_rsia.launch.ros2_values.ValueResolver`.
"""

from dataclasses import dataclass
import os
from typing import Optional

from colcon_rsia.launch.common import join_ns
from colcon_rsia.launch.common import load_yaml
from colcon_rsia.launch.common import MAX_NESTING
from colcon_rsia.launch.common import normalise_ns
from colcon_rsia.launch.common import params_from_sections
from colcon_rsia.launch.common import parse_bool
from colcon_rsia.launch.common import resolve_path
from colcon_rsia.launch.common import ros2_param_sections
from colcon_rsia.launch.common import ros_arguments
from colcon_rsia.launch.common import UnknownArg
from colcon_rsia.launch.handlers import HandlerTable
from colcon_rsia.launch.ir import Action
from colcon_rsia.launch.ir import ComposableNode
from colcon_rsia.launch.ir import DeclareLaunchArgument
from colcon_rsia.launch.ir import GroupAction
from colcon_rsia.launch.ir import Ignored
from colcon_rsia.launch.ir import IncludeLaunchDescription
from colcon_rsia.launch.ir import LoadComposableNodes
from colcon_rsia.launch.ir import Node
from colcon_rsia.launch.ir import Opaque
from colcon_rsia.launch.ir import ParamDict
from colcon_rsia.launch.ir import PushROSNamespace
from colcon_rsia.launch.ir import SetEnv
from colcon_rsia.launch.ir import SetLaunchConfiguration
from colcon_rsia.launch.ir import SetParameter
from colcon_rsia.launch.ir import SetRemap
from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.model import NodeInstance
from colcon_rsia.launch.notes import unique
from colcon_rsia.launch.ros2_values import ValueResolver
from colcon_rsia.launch.substitutions import Call
from colcon_rsia.launch.substitutions import Concat
from colcon_rsia.launch.substitutions import Text
from colcon_rsia.launch.substitutions import Unresolved

# launch actions executed in one load: real systems have a few thousand;
# actions shared in nested Python lists must not multiply without bound
MAX_ACTIONS = 200000

# the type of an action -> the Ros2Executor method executing it, registered
# by `@_ACTIONS.handles(type, ...)`
_ACTIONS = HandlerTable('launch action type')


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
    """Executes ROS 2 launch actions statically.

    :param loader: the :class:`~colcon_rsia.launch.common.Loader` of the load
    :param dict readers: file kind ('ros2' for XML, 'yaml', 'python') ->
      ``reader(path, text, loader, root)`` giving a file's actions; ``root``
      is the parsed XML of an XML file, else None. Handed in, not
      imported: a reader (Python) builds actions, the executor runs them,
      and neither needs the other.
    """

    def __init__(self, loader, readers):  # noqa: D107
        self.loader = loader
        self.readers = readers

    # files

    def run_top(self, path, kind, text, root=None):
        """Read and execute the top-level file."""
        ctx = Ctx(path, dict(self.loader.arguments), '/', [], [],
                  dict(self.loader.environ), [])
        actions = self.actions_of(path, kind, text, root)
        self.execute(actions, ctx, 0)

    def actions_of(self, path, kind, text, root=None):
        """The actions of a ROS 2 launch file of a kind."""
        return self.readers[kind](path, text, self.loader, root)

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
        if not self.loader.enter_include(path, where):
            return
        try:
            text, root, kind = self.loader.read_launch(path)
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
        handler = _ACTIONS[type(action)]
        handler(self, action, ctx, depth, uncertain + action.notes)

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

    def _configuration_name(self, action, ctx, what):
        """The name an action sets; None (noted) when not known."""
        try:
            return self.text(action.name, ctx, [])
        except Unresolved as e:
            self.loader.note(f'{action.location}: {what} name not known '
                             f'({e})')
            return None

    @_ACTIONS.handles(DeclareLaunchArgument)
    def _declare_argument(self, action, ctx, depth, uncertain):
        name = self._configuration_name(action, ctx, 'argument')
        if name is None:
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

    @_ACTIONS.handles(SetLaunchConfiguration)
    def _set_configuration(self, action, ctx, depth, uncertain):
        name = self._configuration_name(action, ctx, 'configuration')
        if name is None:
            return
        if uncertain:
            ctx.configs[name] = UnknownArg(uncertain[0])
            return
        try:
            ctx.configs[name] = self.text(action.value, ctx, [])
        except Unresolved as e:
            ctx.configs[name] = UnknownArg(str(e))

    @_ACTIONS.handles(GroupAction)
    def _group(self, action, ctx, depth, uncertain):
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

    @_ACTIONS.handles(IncludeLaunchDescription)
    def _include(self, action, ctx, depth, uncertain):
        if uncertain:
            ctx = ctx.copy()
            ctx.notes.extend(uncertain)
        self.include(action, ctx, depth)

    @_ACTIONS.handles(PushROSNamespace)
    def _push_namespace(self, action, ctx, depth, uncertain):
        try:
            ns = self.text(action.namespace, ctx, ctx.notes)
            ctx.ns = join_ns(ctx.ns, ns)
        except Unresolved as e:
            ctx.ns = None
            ctx.notes.append(f'{action.location}: pushed namespace not '
                             f'known statically ({e})')
        if uncertain:
            ctx.notes.extend(uncertain)

    @_ACTIONS.handles(SetRemap)
    def _set_remap(self, action, ctx, depth, uncertain):
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

    @_ACTIONS.handles(SetParameter)
    def _set_parameter(self, action, ctx, depth, uncertain):
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

    @_ACTIONS.handles(SetEnv)
    def _set_env(self, action, ctx, depth, uncertain):
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

    @_ACTIONS.handles(Opaque)
    def _opaque(self, action, ctx, depth, uncertain):
        self.loader.note(f'{action.location}: {action.note}')

    @_ACTIONS.handles(ComposableNode)
    def _stray_composable(self, action, ctx, depth, uncertain):
        # launch itself rejects it: a component runs only in a container
        self.loader.note(
            f'{action.location}: a ComposableNode outside a container '
            '(ComposableNodeContainer, LoadComposableNodes) starts nothing')

    @_ACTIONS.handles(LoadComposableNodes)
    def _load_composable(self, action, ctx, depth, uncertain):
        for composable in action.composables:
            self._component(composable, ctx, uncertain)

    @_ACTIONS.handles(Node)
    def _node(self, action, ctx, depth, uncertain):
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
            text = self.values(ctx, notes).substitutions.substitute(text)
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

    # substitutions

    def values(self, ctx, notes, declaring=None):
        """The resolver of values in a scope."""
        return ValueResolver(
            configs=ctx.configs, environ=ctx.environ, current_file=ctx.file,
            find_package=self.loader.find_package, notes=notes,
            declaring=declaring)

    def text(self, value, ctx, notes, declaring=None):
        """The text of a value (literal, parsed substitution or Python)."""
        return self.values(ctx, notes, declaring).text(value)

    def param_value(self, value, ctx, notes):
        """A parameter value: typed as launch_ros types text values."""
        return self.values(ctx, notes).parameter(value)
