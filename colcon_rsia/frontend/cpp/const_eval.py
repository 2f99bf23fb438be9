# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Compile-time constant numbers in C++ expressions (rates, periods).

Literals, ``const``/``constexpr`` variables, ``#define`` macros, casts and
``+ - * /``. Anything else is not a constant: the answer is None. Nothing is
ever executed; macro bodies are read by a small arithmetic parser.
"""

import re

import clang.cindex as ci
from colcon_rsia import safe_files

CK = ci.CursorKind

# how deep an evaluation may go: each implicit conversion, parenthesis and
# constant referring to another is a level, and the real standard library
# wraps a std::chrono constant passed as another duration type in ~10
MAX_DEPTH = 24

_WRAPPERS = frozenset({
    CK.UNEXPOSED_EXPR, CK.PAREN_EXPR, CK.CSTYLE_CAST_EXPR,
    CK.CXX_STATIC_CAST_EXPR, CK.CXX_FUNCTIONAL_CAST_EXPR,
})
_NOT_EXPRESSIONS = frozenset({
    CK.TYPE_REF, CK.NAMESPACE_REF, CK.TEMPLATE_REF})
_NUMBER = re.compile(
    r'^(0[xX][0-9a-fA-F]+|(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)'
    r'[uUlLfF]*$')


def evaluate_number(cursor, depth=0):
    """Return the numeric value of a constant expression, or None."""
    if cursor is None or depth > MAX_DEPTH:
        return None
    value = _evaluate_structure(cursor, depth)
    if value is None:
        # a whole expression spelled as one macro: read the macro
        tokens = [t.spelling for t in source_tokens(cursor)]
        if len(tokens) == 1 and not _NUMBER.match(tokens[0]):
            macros = _Macros(cursor.translation_unit)
            body = macros.get(tokens[0])
            if body is not None:
                value = evaluate_tokens(body, macros, depth + 1)
    return value


def _evaluate_structure(cursor, depth):
    kind = cursor.kind
    if kind in (CK.INTEGER_LITERAL, CK.FLOATING_LITERAL):
        # inside a macro expansion the first token is the literal as spelled
        first = next(iter(cursor.get_tokens()), None)
        return _number(first.spelling) if first is not None else None
    children = [c for c in cursor.get_children()
                if c.kind not in _NOT_EXPRESSIONS]
    if kind in _WRAPPERS and children:
        return evaluate_number(children[-1], depth + 1)
    if kind == CK.UNARY_OPERATOR and len(children) == 1:
        value = evaluate_number(children[0], depth + 1)
        first = next(iter(cursor.get_tokens()), None)
        if value is None or first is None:
            return None
        return -value if first.spelling == '-' else value
    if kind == CK.BINARY_OPERATOR and len(children) == 2:
        left = evaluate_number(children[0], depth + 1)
        right = evaluate_number(children[1], depth + 1)
        operator = binary_operator(cursor, children[0])
        return _apply(operator, left, right)
    if kind == CK.DECL_REF_EXPR:
        return _constant_variable(cursor.referenced, depth)
    return None


def _constant_variable(declaration, depth):
    if declaration is None or declaration.kind != CK.VAR_DECL:
        return None
    tokens = [t.spelling for t in declaration.get_tokens()]
    if not (declaration.type.is_const_qualified() or 'constexpr' in tokens):
        return None  # a variable may change: not a constant rate
    children = [c for c in declaration.get_children()
                if c.kind not in _NOT_EXPRESSIONS]
    return evaluate_number(children[-1], depth + 1) if children else None


def binary_operator(cursor, left):
    """The operator of a binary expression: the token after its left side."""
    end = left.extent.end.offset
    for token in cursor.get_tokens():
        if token.extent.start.offset >= end:
            return token.spelling
    return None


def _apply(operator, left, right):
    if left is None or right is None:
        return None
    if operator == '+':
        return left + right
    if operator == '-':
        return left - right
    if operator == '*':
        return left * right
    if operator == '/':
        return left / right if right else None
    return None


def _number(text):
    match = _NUMBER.match(text)
    if not match:
        return None
    body = match.group(1)
    if body.lower().startswith('0x'):
        return float(int(body, 16))
    return float(body)


def source_tokens(cursor):
    """The tokens written at an expression's place in the source.

    Inside a macro expansion libclang's extent starts at the macro's
    definition; then re-read the tokens at the place of use.
    """
    tokens = list(cursor.get_tokens())
    start, end = cursor.extent.start, cursor.extent.end
    if not tokens or start.file is None:
        return tokens
    first = tokens[0].location
    if first.file is not None and first.file.name == start.file.name and \
            first.line == start.line and first.column == start.column:
        return tokens
    tu = cursor.translation_unit
    extent = ci.SourceRange.from_locations(
        ci.SourceLocation.from_position(
            tu, start.file, start.line, start.column),
        ci.SourceLocation.from_position(tu, end.file, end.line, end.column))
    return list(tu.get_tokens(extent=extent))


_DEFINE = re.compile(r'^[ \t]*#[ \t]*define[ \t]+(\w+)(?![\w(])(.*)$', re.MULTILINE)
_TOKEN = re.compile(r'0[xX][0-9a-fA-F]+|(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?'
                    r'[uUlLfF]*|\w+|\S')


class _Macros:
    """Object-like macros of the TU's own files, read from their text.

    Only needed when a rate is spelled as a macro whose body is an
    expression; the files are read on first use.
    """

    def __init__(self, tu):
        self._tu = tu

    def _definitions(self):
        cached = getattr(self._tu, '_rsia_macros', None)
        if cached is None:
            cached = {}
            files = [self._tu.spelling] + [
                i.include.name for i in self._tu.get_includes()
                if i.include is not None]
            for name in files:
                # system headers define no rates of the package
                if name.startswith(safe_files.SYSTEM_PREFIXES):
                    continue
                try:
                    # checked: a header may be a link to /dev/zero
                    text = safe_files.read_text(name)
                except OSError:
                    continue
                text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.DOTALL)
                for match in _DEFINE.finditer(text):
                    body = match.group(2).split('//')[0]
                    cached.setdefault(match.group(1), _TOKEN.findall(body))
            self._tu._rsia_macros = cached
        return cached

    def get(self, name):
        """The body tokens of an object-like macro, or None."""
        return self._definitions().get(name) or None


def evaluate_tokens(tokens, macros=None, depth=0):
    """Evaluate ``+ - * / ( )`` over numbers and macro names, or None."""
    macros = macros or {}
    expanded = []
    for token in tokens:
        if _NUMBER.match(token) or token in '+-*/()':
            expanded.append(token)
        elif depth < MAX_DEPTH and macros.get(token) is not None:
            value = evaluate_tokens(macros.get(token), macros, depth + 1)
            if value is None:
                return None
            expanded.append(repr(value))
        else:
            return None
    parser = _Parser(expanded)
    try:
        value = parser.expression()
    except (IndexError, ValueError, ZeroDivisionError):
        return None
    return value if parser.position == len(expanded) else None


class _Parser:
    """Recursive descent over tokens: expression, term, factor."""

    def __init__(self, tokens):
        self.tokens = tokens
        self.position = 0

    def _peek(self):
        if self.position < len(self.tokens):
            return self.tokens[self.position]
        return None

    def _take(self):
        token = self.tokens[self.position]
        self.position += 1
        return token

    def expression(self):
        value = self.term()
        while self._peek() in ('+', '-'):
            value = value + self.term() if self._take() == '+' \
                else value - self.term()
        return value

    def term(self):
        value = self.factor()
        while self._peek() in ('*', '/'):
            if self._take() == '*':
                value *= self.factor()
            else:
                value /= self.factor()
        return value

    def factor(self):
        token = self._take()
        if token == '-':
            return -self.factor()
        if token == '+':
            return self.factor()
        if token == '(':
            value = self.expression()
            if self._take() != ')':
                raise ValueError('unbalanced parenthesis')
            return value
        value = _number(token)
        if value is None:
            raise ValueError(f'not a number: {token}')
        return value


# --- std::chrono durations ---------------------------------------------------

# the suffixes of the std::chrono literal operators, in seconds
_CHRONO_SUFFIXES = {
    'h': 3600.0, 'min': 60.0, 's': 1.0, 'ms': 1e-3, 'us': 1e-6, 'ns': 1e-9}
_CHRONO_LITERAL = re.compile(
    r'^((?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)(h|min|s|ms|us|ns)$')
_RATIO = re.compile(r'std::(?:__1::)?ratio<\s*(\d+)[lLuU]*\s*(?:,\s*(\d+)[lLuU]*\s*)?>')


def is_chrono_duration(type_):
    """Whether a libclang type is a ``std::chrono::duration``."""
    # the type itself, not one naming a duration among its arguments (a
    # std::chrono::time_point)
    canonical = re.sub(r'^(?:(?:const|volatile)\s+)*', '',
                       type_.get_canonical().spelling)
    return canonical.startswith(
        ('std::chrono::duration<', 'std::__1::chrono::duration<'))


def _duration_unit(type_):
    """Seconds per tick of a std::chrono::duration type, or None."""
    canonical = type_.get_canonical().spelling
    start = canonical.find('chrono::duration<')
    if start < 0:
        return None
    match = _RATIO.search(canonical, start)
    if match is None:
        return 1.0  # duration<Rep>: seconds
    numerator = float(match.group(1))
    denominator = float(match.group(2) or 1)
    return numerator / denominator


def evaluate_duration_seconds(cursor, depth=0):
    """Seconds of a constant std::chrono duration expression, or None.

    Reads ``100ms`` (the literal operators), ``std::chrono::milliseconds(
    100)`` and other duration constructors (the period ratio comes from the
    type), conversions between durations and constant variables holding one.
    """
    if cursor is None or depth > MAX_DEPTH:
        return None
    tokens = [t.spelling for t in source_tokens(cursor)]
    if len(tokens) == 1:
        match = _CHRONO_LITERAL.match(tokens[0])
        if match:
            return float(match.group(1)) * _CHRONO_SUFFIXES[match.group(2)]
    kind = cursor.kind
    children = [c for c in cursor.get_children()
                if c.kind not in _NOT_EXPRESSIONS]
    if kind == CK.DECL_REF_EXPR:
        declaration = cursor.referenced
        if declaration is None or declaration.kind != CK.VAR_DECL:
            return None
        tokens = [t.spelling for t in declaration.get_tokens()]
        if not (declaration.type.is_const_qualified() or
                'constexpr' in tokens):
            return None
        inits = [c for c in declaration.get_children()
                 if c.kind not in _NOT_EXPRESSIONS]
        return evaluate_duration_seconds(inits[-1], depth + 1) \
            if inits else None
    if kind == CK.CALL_EXPR and cursor.referenced is not None and \
            cursor.referenced.kind == CK.CONSTRUCTOR and \
            is_chrono_duration(cursor.type):
        arguments = list(cursor.get_arguments())
        if len(arguments) != 1:
            return None
        if is_chrono_duration(arguments[0].type):
            return evaluate_duration_seconds(arguments[0], depth + 1)
        value = evaluate_number(arguments[0], depth + 1)
        unit = _duration_unit(cursor.type)
        return value * unit if value is not None and unit else None
    if kind == CK.BINARY_OPERATOR and len(children) == 2:
        left = evaluate_duration_seconds(children[0], depth + 1)
        right = evaluate_number(children[1], depth + 1)
        operator = binary_operator(cursor, children[0])
        if left is not None and right is not None and operator in ('*', '/'):
            return _apply(operator, left, right)
        return None
    if len(children) == 1:
        # implicit conversions, parentheses, temporaries
        return evaluate_duration_seconds(children[0], depth + 1)
    return None


# classes made of (seconds), (seconds, nanoseconds) or a std::chrono
# duration: ros::Duration, ros::WallDuration, rclcpp::Duration
_PERIOD_CLASSES = ('Duration', 'WallDuration')
# boost::posix_time durations: class name -> seconds per count
_POSIX_DURATIONS = {
    'hours': 3600.0, 'minutes': 60.0, 'seconds': 1.0,
    'milliseconds': 1e-3, 'microseconds': 1e-6,
}


def evaluate_period_seconds(cursor):
    """Seconds of a constant period of any clock library, or None.

    std::chrono durations, ``ros::Duration(0.1)``, ``rclcpp::Duration(s,
    ns)`` or from a chrono duration, ``rclcpp::Duration::from_seconds(x)``
    and ``boost::posix_time::seconds(2)`` and its kin; the first duration
    made in the expression decides.
    """
    if cursor is None:
        return None
    seconds = evaluate_duration_seconds(cursor)
    if seconds:
        return seconds
    for current in cursor.walk_preorder():
        referenced = current.referenced \
            if current.kind == CK.CALL_EXPR else None
        if referenced is None:
            continue
        arguments = list(current.get_arguments())
        parent = referenced.semantic_parent
        if referenced.spelling == 'from_seconds' and parent is not None and \
                parent.spelling == 'Duration':
            return evaluate_number(arguments[0]) if arguments else None
        if referenced.kind != CK.CONSTRUCTOR:
            continue
        name = referenced.spelling
        if name in _POSIX_DURATIONS:
            # (the real constructors take a defaulted enable_if argument)
            count = evaluate_number(arguments[0]) if arguments else None
            return count * _POSIX_DURATIONS[name] \
                if count is not None else None
        if name in _PERIOD_CLASSES:
            return _period_object_seconds(arguments)
    return None


def _period_object_seconds(arguments):
    values = [evaluate_number(a) for a in arguments]
    if len(values) == 1 and values[0]:
        return values[0]
    if len(arguments) == 1 and is_chrono_duration(arguments[0].type):
        # rclcpp::Duration from std::chrono::milliseconds(50)
        return evaluate_duration_seconds(arguments[0])
    if len(values) == 2 and None not in values:
        return values[0] + values[1] * 1e-9
    return None
