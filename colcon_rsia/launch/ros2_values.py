# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The text of a ROS 2 launch value in the scope it is used in.

A value of :mod:`colcon_rsia.launch.ir` is literal text, a parsed ``$(...)``
substitution of an XML or YAML file (:mod:`colcon_rsia.launch.substitutions`)
or a substitution written in Python (``LaunchConfiguration``…), or a list of
these. :meth:`ValueResolver.resolve` turns any of them into text, one
handler per type of value.
"""

import os

from colcon_rsia.launch.common import argument_text
from colcon_rsia.launch.common import parse_bool
from colcon_rsia.launch.common import typed_value
from colcon_rsia.launch.handlers import HandlerTable
from colcon_rsia.launch.ir import BoolOp
from colcon_rsia.launch.ir import EnvironmentVariable
from colcon_rsia.launch.ir import LaunchConfiguration
from colcon_rsia.launch.ir import PackagePath
from colcon_rsia.launch.ir import PathJoinSubstitution
from colcon_rsia.launch.ir import PythonExpression
from colcon_rsia.launch.ir import ThisFile
from colcon_rsia.launch.ir import TypedValue
from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.safe_eval import evaluate
from colcon_rsia.launch.safe_eval import to_text
from colcon_rsia.launch.substitutions import Call
from colcon_rsia.launch.substitutions import Concat
from colcon_rsia.launch.substitutions import MAX_VALUE_LENGTH
from colcon_rsia.launch.substitutions import Resolver
from colcon_rsia.launch.substitutions import Text
from colcon_rsia.launch.substitutions import Unresolved

# parts one value may be made of: a value built by doubling itself in a
# loop must not take exponential time to resolve
MAX_VALUE_PARTS = 100000
# values inside values (lists in lists, defaults of defaults): a Python
# launch file can build them in a loop; two Python frames a level keep the
# stack well below its limit of 1000
MAX_VALUE_DEPTH = 200

# the values that are substitutions: a parameter list holding one of them
# is one text (launch_ros joins it), not a list of values
SUBSTITUTIONS = (Text, Concat, Call, LaunchConfiguration, PackagePath,
                 EnvironmentVariable, PathJoinSubstitution, PythonExpression,
                 ThisFile, BoolOp, UnknownValue)

# the type of a value -> the ValueResolver method resolving it, registered
# by `@_VALUES.handles(type, ...)`
_VALUES = HandlerTable('launch value type')


class ValueResolver:
    """Resolves values over a scope's launch configurations and environment.

    :param dict configs: launch configuration name -> text or
      :class:`UnknownArg`
    :param dict environ: the environment variables in scope
    :param str current_file: the launch file the value is written in
    :param find_package: the loader's ``find_package``
    :param list notes: receives notes about placeholders (``$(anon)``)
    :param declaring: the argument whose default is being resolved (it may
      not refer to itself)
    """

    def __init__(self, *, configs, environ, current_file,  # noqa: D107
                 find_package, notes, declaring=None):
        self.configs = configs
        self.environ = environ
        self.current_file = current_file
        self.find_package = find_package
        self.declaring = declaring
        self.substitutions = Resolver(
            dialect='ros2', lookup_arg=self.argument, environ=environ,
            find_package=find_package, current_file=current_file,
            notes=notes)
        self.budget = MAX_VALUE_PARTS

    def argument(self, name):
        """The text of a launch configuration (``$(var)``).

        :raises Unresolved: when it is not set or not known
        """
        return argument_text(self.configs, name, declaring=self.declaring)

    def text(self, value):
        """The text of a value, within the limits of one value."""
        self.budget = MAX_VALUE_PARTS
        result = self.resolve(value, 0)
        if len(result) > MAX_VALUE_LENGTH:
            raise Unresolved('a substituted value is too long')
        return result

    def resolve(self, value, depth):
        """The text of a value of any kind (a part of the value at depth).

        :raises Unresolved: when the value is not known statically
        """
        self.budget -= 1
        if self.budget < 0 or depth > MAX_VALUE_DEPTH:
            raise Unresolved('a value is built from too many parts')
        handler = _handler(type(value))
        if handler is None:
            raise Unresolved(f'a {type(value).__name__} is not a text value')
        return handler(self, value, depth + 1)

    def parameter(self, value):
        """A parameter value: typed as launch_ros types text values."""
        if isinstance(value, TypedValue):
            return self.text(value.value)
        if value is None or isinstance(value, (bool, int, float)):
            return value
        if isinstance(value, (list, tuple)):
            if any(isinstance(v, SUBSTITUTIONS) for v in value):
                return typed_value(self.text(list(value)))
            items = []
            for v in value:
                if isinstance(v, (list, tuple, dict)):
                    raise Unresolved('nested lists are not parameter values')
                items.append(v if isinstance(v, (str, bool, int, float))
                             else self.parameter(v))
            return items
        if isinstance(value, dict):
            raise Unresolved('a dictionary is not a parameter value')
        return typed_value(self.text(value))

    # one handler per type of value

    @_VALUES.handles(str)
    def _literal(self, value, depth):
        return value

    @_VALUES.handles(bool)
    def _boolean(self, value, depth):
        return 'true' if value else 'false'

    @_VALUES.handles(int, float)
    def _number(self, value, depth):
        return str(value)

    @_VALUES.handles(Text, Concat, Call)
    def _substitution(self, value, depth):
        return self.substitutions.resolve(value)

    @_VALUES.handles(list, tuple)
    def _parts(self, value, depth):
        parts = []
        size = 0
        for v in value:
            part = self.resolve(v, depth)
            size += len(part)
            if size > MAX_VALUE_LENGTH:
                raise Unresolved('a substituted value is too long')
            parts.append(part)
        return ''.join(parts)

    @_VALUES.handles(UnknownValue)
    def _unknown(self, value, depth):
        raise Unresolved(value.reason)

    @_VALUES.handles(LaunchConfiguration)
    def _launch_config(self, value, depth):
        name = self.resolve(value.name, depth)
        if name not in self.configs and value.default is not None:
            return self.resolve(value.default, depth)
        return self.argument(name)

    @_VALUES.handles(PackagePath)
    def _package_path(self, value, depth):
        package = self.resolve(value.package, depth)
        return self.find_package(package, value.kind)

    @_VALUES.handles(EnvironmentVariable)
    def _env_var(self, value, depth):
        name = self.resolve(value.name, depth)
        if name in self.environ:
            return self.environ[name]
        if value.default is not None:
            return self.resolve(value.default, depth)
        raise Unresolved(f'environment variable {name} is not set')

    @_VALUES.handles(PathJoinSubstitution)
    def _path_join(self, value, depth):
        parts = [self.resolve(p, depth) for p in value.parts]
        return os.path.join(*parts) if parts else ''

    @_VALUES.handles(PythonExpression)
    def _python_expression(self, value, depth):
        expression = self.resolve(value.parts, depth)
        return to_text(evaluate(expression, lookup=self.argument))

    @_VALUES.handles(ThisFile)
    def _this_file(self, value, depth):
        path = os.path.abspath(self.current_file)
        return os.path.dirname(path) if value.directory else path

    @_VALUES.handles(TypedValue)
    def _typed(self, value, depth):
        return self.resolve(value.value, depth)

    @_VALUES.handles(BoolOp)
    def _bool_op(self, value, depth):
        texts = [self.resolve(v, depth) for v in value.operands]
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


def _handler(value_type):
    """The handler of a type of value or of its nearest base; None if none.

    The nearest base: a subclass of str is text, as ``isinstance`` has it.
    """
    for cls in value_type.__mro__:
        handler = _VALUES.get(cls)
        if handler is not None:
            return handler
    return None
