# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The ``$(name args…)`` substitutions of ROS 1 and ROS 2 launch files.

:func:`parse` turns an attribute into a tree of :class:`Text`,
:class:`Concat` and :class:`Call`; a :class:`Resolver` turns the tree into
text over what is statically known (arguments, the environment, package
locations). Whatever cannot be known raises :class:`Unresolved`.
"""

from dataclasses import dataclass
import os
from typing import List
from typing import Optional

from colcon_rsia.launch.handlers import HandlerTable
from colcon_rsia.launch.notes import shorten
from colcon_rsia.launch.safe_eval import evaluate
from colcon_rsia.launch.safe_eval import to_text
from colcon_rsia.launch.safe_eval import Unresolved

__all__ = [
    'Call', 'Concat', 'Resolver', 'Text', 'Unresolved', 'parse',
    'MAX_VALUE_LENGTH']

# substitutions nested deeper than this ($(a $(b $(c …)))) are not
# written by people (elements and YAML: common.MAX_NESTING)
MAX_SUBSTITUTION_NESTING = 16
# the longest value a substitution may produce: arguments that double
# themselves (a=$(arg b)$(arg b)…) must not exhaust memory
MAX_VALUE_LENGTH = 100000

_SPACE = ' \t\r\n'


@dataclass
class Text:
    """Literal text."""

    value: str


@dataclass
class Concat:
    """Parts whose texts are joined."""

    parts: list


@dataclass
class Call:
    """A ``$(name args…)`` substitution as written."""

    name: str
    args: List[object]
    raw: Optional[str]  # the body of $(eval …) as written
    source: str         # the whole substitution text, for messages


def parse(text, *, quotes=False):
    """Parse substitutions in a text.

    :param str text: the attribute value
    :param bool quotes: arguments may be quoted with ' or " (ROS 2)
    :returns: a :class:`Text`, :class:`Concat` or :class:`Call`
    :raises Unresolved: for unbalanced or empty substitutions
    """
    parser = _Parser(text, quotes)
    parts = parser.top()
    return _concat(parts)


def _concat(parts):
    if not parts:
        return Text('')
    if len(parts) == 1:
        return parts[0]
    return Concat(parts)


class _Parser:

    def __init__(self, text, quotes):
        self.text = text
        self.pos = 0
        self.quotes = quotes

    def _starts_call(self):
        return self.text.startswith('$(', self.pos)

    def top(self):
        parts = []
        start = self.pos
        while True:
            index = self.text.find('$(', self.pos)
            if index < 0:
                break
            if index > start:
                parts.append(Text(self.text[start:index]))
            self.pos = index
            parts.append(self.call(1))
            start = self.pos
        if start < len(self.text):
            parts.append(Text(self.text[start:]))
        return parts

    def call(self, depth):
        if depth > MAX_SUBSTITUTION_NESTING:
            raise Unresolved('substitutions are nested too deeply')
        text = self.text
        start = self.pos
        self.pos += 2
        self._skip_space()
        name_start = self.pos
        while self.pos < len(text) and text[self.pos] not in _SPACE + ')$':
            self.pos += 1
        name = text[name_start:self.pos]
        if not name:
            raise Unresolved(
                f'empty or malformed substitution in {shorten(text[start:])}')
        if name == 'eval':
            raw = self._raw_body(start)
            return Call(name, [], raw, text[start:self.pos])
        args = []
        while True:
            self._skip_space()
            if self.pos >= len(text):
                raise Unresolved(
                    f'unterminated substitution {shorten(text[start:])}')
            if text[self.pos] == ')':
                self.pos += 1
                break
            args.append(self._token(depth))
        return Call(name, args, None, text[start:self.pos])

    def _skip_space(self):
        while self.pos < len(self.text) and self.text[self.pos] in _SPACE:
            self.pos += 1

    def _token(self, depth):
        text = self.text
        parts = []
        buf = []
        while self.pos < len(text):
            c = text[self.pos]
            if c in _SPACE or c == ')':
                break
            if self._starts_call():
                _flush(buf, parts)
                parts.append(self.call(depth + 1))
                continue
            if self.quotes and c in '\'"':
                _flush(buf, parts)
                parts.extend(self._quoted(c, depth))
                continue
            buf.append(c)
            self.pos += 1
        _flush(buf, parts)
        return _concat(parts)

    def _quoted(self, quote, depth):
        text = self.text
        start = self.pos
        self.pos += 1
        parts = []
        buf = []
        while True:
            if self.pos >= len(text):
                raise Unresolved(
                    f'unterminated quote in {shorten(text[start:])}')
            c = text[self.pos]
            if c == quote:
                self.pos += 1
                break
            if self._starts_call():
                _flush(buf, parts)
                parts.append(self.call(depth + 1))
                continue
            buf.append(c)
            self.pos += 1
        _flush(buf, parts)
        if not parts:
            parts.append(Text(''))
        return parts

    def _raw_body(self, start):
        text = self.text
        body_start = self.pos
        level = 0
        quote = None
        while self.pos < len(text):
            c = text[self.pos]
            if quote:
                if c == quote:
                    quote = None
            elif c in '\'"':
                quote = c
            elif c == '(':
                level += 1
            elif c == ')':
                if level == 0:
                    body = text[body_start:self.pos]
                    self.pos += 1
                    return body.strip()
                level -= 1
            self.pos += 1
        raise Unresolved(f'unterminated substitution {shorten(text[start:])}')


def _flush(buf, parts):
    if buf:
        parts.append(Text(''.join(buf)))
        buf.clear()


def _limit(value):
    if len(value) > MAX_VALUE_LENGTH:
        raise Unresolved('a substituted value is too long')
    return value


# the parts of a parsed tree (their types) and the substitutions of each
# dialect (their names) -> the Resolver method resolving them, registered by
# `@_TREE.handles(type)`, `@_ROS1.handles(name)`, `@_ROS2.handles(name)`
_TREE = HandlerTable('substitution part type')
_ROS1 = HandlerTable('ROS 1 substitution')
_ROS2 = HandlerTable('ROS 2 substitution')
_DIALECTS = {'ros1': _ROS1, 'ros2': _ROS2}


class Resolver:
    """Resolve substitutions over what is known statically.

    :param str dialect: 'ros1' or 'ros2'
    :param lookup_arg: callable name -> str for ``$(arg)``/``$(var)``; raises
      :class:`Unresolved` for an unknown argument
    :param environ: mapping of environment variables
    :param find_package: callable (package, kind) -> str path where kind is
      'find' (ROS 1), 'share' or 'prefix'; raises :class:`Unresolved`
    :param str current_file: the launch file being read
    :param list notes: receives notes about values that are placeholders
    """

    def __init__(self, *, dialect, lookup_arg, environ,  # noqa: D107
                 find_package, current_file, notes):
        self.dialect = dialect
        self.lookup_arg = lookup_arg
        self.environ = environ
        self.find_package = find_package
        self.current_file = current_file
        self.notes = notes

    def substitute(self, text):
        """The value of an attribute text with its substitutions resolved."""
        if '$(' not in text:
            return text
        return self.resolve(parse(text, quotes=self.dialect == 'ros2'))

    def resolve(self, sub):
        """The text of a parsed substitution tree."""
        return _TREE[type(sub)](self, sub)

    @_TREE.handles(Text)
    def _text(self, sub):
        return sub.value

    @_TREE.handles(Concat)
    def _concat(self, sub):
        total = []
        size = 0
        for part in sub.parts:
            value = self.resolve(part)
            size += len(value)
            if size > MAX_VALUE_LENGTH:
                raise Unresolved('a substituted value is too long')
            total.append(value)
        return ''.join(total)

    @_TREE.handles(Call)
    def _call(self, sub):
        if sub.name == 'eval':
            return _limit(self._eval(sub))
        handler = _DIALECTS[self.dialect].get(sub.name)
        if handler is None:
            raise Unresolved(f'unknown substitution {shorten(sub.source)}')
        args = [self.resolve(a) for a in sub.args]
        return _limit(handler(self, args, sub))

    # ROS 1 and ROS 2 handlers

    @_ROS1.handles('arg')
    @_ROS2.handles('var')
    def _arg(self, args, sub):
        if len(args) != 1:
            raise Unresolved(f'{sub.source} needs exactly one name')
        return self.lookup_arg(args[0])

    @_ROS1.handles('env')
    @_ROS2.handles('env')
    def _env(self, args, sub):
        if len(args) == 1 or (self.dialect == 'ros2' and len(args) == 2):
            value = self.environ.get(args[0])
            if value is not None:
                return value
            if len(args) == 2:
                return args[1]
            raise Unresolved(f'environment variable {args[0]} is not set '
                             f'({sub.source})')
        raise Unresolved(f'{sub.source}: wrong number of arguments')

    @_ROS1.handles('optenv')
    def _optenv(self, args, sub):
        if not args:
            raise Unresolved(f'{sub.source} needs a variable name')
        value = self.environ.get(args[0])
        if value is not None:
            return value
        return ' '.join(args[1:])

    @_ROS1.handles('find')
    @_ROS2.handles('find-pkg-share', 'find-pkg-prefix')
    def _find(self, args, sub):
        if len(args) != 1:
            raise Unresolved(f'{sub.source} needs exactly one package')
        kind = {'find': 'find', 'find-pkg-share': 'share',
                'find-pkg-prefix': 'prefix'}[sub.name]
        return self.find_package(args[0], kind)

    @_ROS1.handles('dirname')
    @_ROS2.handles('dirname')
    def _dirname(self, args, sub):
        return os.path.dirname(os.path.abspath(self.current_file))

    @_ROS2.handles('filename')
    def _filename(self, args, sub):
        return os.path.abspath(self.current_file)

    @_ROS1.handles('anon')
    @_ROS2.handles('anon')
    def _anon(self, args, sub):
        if len(args) != 1:
            raise Unresolved(f'{sub.source} needs exactly one name')
        placeholder = f'{args[0]}_anon'
        note = (f'{sub.source} is a unique name chosen at run time; '
                f"shown as '{placeholder}'")
        if note not in self.notes:
            self.notes.append(note)
        return placeholder

    @_ROS2.handles('find-exec', 'exec-in-pkg', 'command', 'param')
    def _not_static(self, args, sub):
        raise Unresolved(f'{shorten(sub.source)} is only known at run time')

    def _eval(self, sub):
        body = sub.raw
        if self.dialect == 'ros2':
            body = _unquote(body)
        text = self.resolve(parse(body, quotes=False))
        functions = {
            'arg': self._eval_arg,
            'env': lambda name: self._env([name], sub),
            'optenv': lambda name, default='': self._optenv(
                [name, default], sub),
            'find': lambda pkg: self.find_package(pkg, 'find'),
            'dirname': lambda: self._dirname([], sub),
        }
        try:
            value = evaluate(text, lookup=self._eval_arg, functions=functions)
        except TypeError:  # a function called with the wrong arguments
            raise Unresolved(f'{shorten(sub.source)}: wrong arguments')
        return to_text(value)

    def _eval_arg(self, name):
        if not isinstance(name, str):
            raise Unresolved('arg() needs a name')
        value = self.lookup_arg(name)
        return _auto(value) if self.dialect == 'ros1' else value


def _auto(text):
    """A ROS 1 argument as ``$(eval)`` sees it: a number, bool or text."""
    stripped = text.strip()
    for convert in (int, float):
        try:
            return convert(stripped)
        except ValueError:
            pass
    if stripped.lower() in ('true', 'false'):
        return stripped.lower() == 'true'
    return text


def _unquote(body):
    if len(body) >= 2 and body[0] in '\'"' and body[-1] == body[0] and \
            body[0] not in body[1:-1]:
        return body[1:-1]
    return body
