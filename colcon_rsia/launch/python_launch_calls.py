# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The calls the Python launch interpreter knows, but of the file's functions.

A part of :class:`colcon_rsia.launch.python_launch_interpreter.Interpreter`:
methods of lists, dictionaries and strings, a few built-ins, ``os.path``
and ``os.environ``, and the launch API (by the last part of its name, in
:data:`colcon_rsia.launch.python_launch_api.LAUNCH_API`).
"""

import os
import string

from colcon_rsia.launch.python_launch_api import ArgError
from colcon_rsia.launch.python_launch_api import Args
from colcon_rsia.launch.python_launch_api import LAUNCH_API
from colcon_rsia.launch.python_launch_values import is_hashable
from colcon_rsia.launch.python_launch_values import LAUNCH_MODULES
from colcon_rsia.launch.python_launch_values import LaunchDescription
from colcon_rsia.launch.python_launch_values import MAX_LOOP
from colcon_rsia.launch.python_launch_values import MAX_SIZE
from colcon_rsia.launch.python_launch_values import safe_format_spec
from colcon_rsia.launch.python_launch_values import SCALARS


class LibraryCalls:
    """How the interpreter calls what the file imports or is given."""

    def method(self, bound, args, kwargs, node):
        """A method of a value the interpreter built (list, dict, str…)."""
        obj, name = bound.obj, bound.name
        if isinstance(obj, LaunchDescription) and name in (
                'add_action', 'add_entity') and len(args) == 1:
            obj.entities.extend(self.mark(args))
            return None
        if isinstance(obj, list):
            if name == 'append' and len(args) == 1:
                if len(obj) >= MAX_SIZE:
                    return self.unknown(node, 'list too large')
                obj.append(self.marked(args[0]))
                return None
            if name == 'extend' and len(args) == 1:
                items = self.sequence(args[0]) if not isinstance(
                    args[0], (list, tuple)) else list(args[0])
                if items is None:
                    obj.append(self.unknown(node, 'extend with a value not '
                                            'known statically'))
                else:
                    self.grow(obj, items, node)
                return None
            if name == 'insert' and len(args) == 2 and isinstance(
                    args[0], int):
                obj.insert(args[0], self.marked(args[1]))
                return None
            if name == 'copy' and not args:
                return list(obj)
        if isinstance(obj, dict):
            if name == 'items' and not args:
                return [(k, v) for k, v in obj.items()]
            if name == 'keys' and not args:
                return list(obj)
            if name == 'values' and not args:
                return list(obj.values())
            if name == 'get' and 1 <= len(args) <= 2 and is_hashable(args[0]):
                return obj.get(args[0], args[1] if len(args) > 1 else None)
            if name == 'update' and len(args) == 1 and isinstance(
                    args[0], dict):
                obj.update(args[0])
                return None
            if name == 'copy' and not args:
                return dict(obj)
        if isinstance(obj, str) and name in _STR_METHODS:
            return self.str_method(obj, name, args, kwargs, node)
        return self.unknown(node, f'method {name}() of a '
                            f'{type(obj).__name__} not interpreted')

    def str_method(self, text, name, args, kwargs, node):
        """A method of a known string, within the size limits."""
        if name == 'format':
            if not all(isinstance(a, SCALARS) for a in
                       list(args) + list(kwargs.values())):
                return self.unknown(node, 'format() of values not known '
                                    'before launch')
            try:
                fields = [(f, spec or '') for _, f, spec, _ in
                          string.Formatter().parse(text) if f is not None]
            except ValueError:
                return self.unknown(node, 'malformed format string')
            if any(not (f == '' or f.isidentifier() or f.isdigit()) or
                   not safe_format_spec(spec) for f, spec in fields):
                return self.unknown(node, 'format fields other than names '
                                    'and positions not interpreted')
            try:
                return self.limit(text.format(*args, **kwargs), node)
            except (IndexError, KeyError, ValueError) as e:
                return self.unknown(node, f'format() fails ({e})')
        if name == 'join' and len(args) == 1 and not kwargs:
            items = self.sequence(args[0])
            if items is None or not all(isinstance(i, str) for i in items):
                return self.unknown(node, 'join() of values not known '
                                    'statically')
            if sum(map(len, items)) + len(text) * len(items) > MAX_SIZE:
                return self.unknown(node, 'value too large')
            return self.limit(text.join(items), node)
        if name == 'replace' and len(args) >= 2 and all(
                isinstance(a, str) for a in args[:2]):
            count = text.count(args[0]) if args[0] else len(text) + 1
            if len(text) + count * len(args[1]) > MAX_SIZE:
                return self.unknown(node, 'value too large')
        if kwargs or not all(isinstance(a, (str, int)) or a is None
                             for a in args):
            return self.unknown(node, f'{name}() arguments not known')
        try:
            value = getattr(text, name)(*args)
        except (TypeError, ValueError) as e:
            return self.unknown(node, f'{name}() fails ({e})')
        return self.limit(value, node)

    def environ(self, name, default, node, *, required=False):
        """An environment variable of the load (``os.environ``)."""
        if not isinstance(name, str):
            return self.unknown(node, 'environment variable name not known')
        if name in self.loader.environ:
            return self.loader.environ[name]
        if required:
            return self.unknown(node, f'environment variable {name} is not '
                                'set')
        return default

    def library(self, qualname, args, kwargs, node):
        """A function or class the file imports: launch API, os.path…."""
        module, _, name = qualname.rpartition('.')
        top = qualname.split('.')[0]
        if qualname.startswith('builtins.'):
            return self.builtin(name, args, kwargs, node)
        if top in LAUNCH_MODULES:
            handler = LAUNCH_API.get(name)
            if handler is not None:
                try:
                    return handler(self, Args(args, kwargs), node)
                except ArgError as e:
                    return self.unknown(node, f'{name}(): {e}')
            return self.unknown(node, f'{qualname}() not interpreted')
        if qualname in ('os.path.join', 'os.path.dirname',
                        'os.path.basename', 'os.path.abspath',
                        'os.path.normpath'):
            if kwargs or not all(isinstance(a, str) for a in args) or (
                    not args):
                return self.unknown(node, f'{qualname}() of values not '
                                    'known statically')
            return self.limit(getattr(os.path, name)(*args), node)
        if qualname in ('os.environ.get', 'os.getenv'):
            default = args[1] if len(args) > 1 else kwargs.get('default')
            return self.environ(args[0] if args else None, default, node)
        return self.unknown(node, f'call of {qualname}() not interpreted')

    def builtin(self, name, args, kwargs, node):
        """A Python built-in function of known arguments."""
        if name in ('str', 'int', 'float', 'bool') and len(args) <= 1 and \
                not kwargs:
            if not args:
                return {'str': '', 'int': 0, 'float': 0.0,
                        'bool': False}[name]
            if isinstance(args[0], SCALARS):
                try:
                    return self.limit(
                        {'str': str, 'int': int, 'float': float,
                         'bool': bool}[name](args[0]), node)
                except (TypeError, ValueError) as e:
                    return self.unknown(node, f'{name}() fails ({e})')
        if name in ('list', 'tuple') and len(args) <= 1 and not kwargs:
            items = self.sequence(args[0]) if args else []
            if items is not None:
                return items if name == 'list' else tuple(items)
        if name == 'dict' and not args:
            return dict(kwargs)
        if name == 'len' and len(args) == 1 and isinstance(
                args[0], (str, list, tuple, dict)):
            return len(args[0])
        if name == 'range' and 1 <= len(args) <= 3 and all(
                isinstance(a, int) for a in args):
            try:
                values = range(*args)
            except ValueError as e:
                return self.unknown(node, f'range() fails ({e})')
            if len(values) > MAX_LOOP:
                return self.unknown(node, 'range() too long')
            return list(values)
        if name in ('enumerate', 'zip', 'sorted', 'reversed') and \
                not kwargs:
            sequences = [self.sequence(a) for a in args]
            if args and all(s is not None for s in sequences):
                if name == 'enumerate' and len(args) == 1:
                    return list(enumerate(sequences[0]))
                if name == 'zip':
                    return list(zip(*sequences))
                if name == 'reversed' and len(args) == 1:
                    return list(reversed(sequences[0]))
                if name == 'sorted' and len(args) == 1 and all(
                        isinstance(v, str) for v in sequences[0]):
                    return sorted(sequences[0])
        if name == 'print':
            return None
        return self.unknown(node, f'{name}() not interpreted')


_STR_METHODS = frozenset((
    'format', 'join', 'replace', 'lower', 'upper', 'strip', 'lstrip',
    'rstrip', 'split', 'startswith', 'endswith'))
