# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A unit's tokens as text: brackets, literals, constant periods.

What the token reader of :mod:`token_facts` asks of a run of tokens,
without a cursor: which bracket closes which, the text as written, the
value of a string literal or of a constant duration.
"""

from dataclasses import dataclass
import re

import clang.cindex as ci
from colcon_rsia.frontend.cpp.strings import unquote

OPENING = {'(': ')', '[': ']', '{': '}'}
CLOSING = {v: k for k, v in OPENING.items()}
# seconds per unit of the chrono literals and of the duration types named
# in a period: `100ms`, `std::chrono::milliseconds(100)`
_CHRONO_SUFFIX = {'h': 3600.0, 'min': 60.0, 's': 1.0, 'ms': 1e-3,
                  'us': 1e-6, 'ns': 1e-9}
_DURATION_TYPES = {
    'hours': 3600.0, 'minutes': 60.0, 'seconds': 1.0, 'milliseconds': 1e-3,
    'microseconds': 1e-6, 'nanoseconds': 1e-9, 'Duration': 1.0,
    'WallDuration': 1.0, 'from_seconds': 1.0, 'duration': 1.0}
_NUMBER = re.compile(
    r'^(\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)'
    r'(h|min|s|ms|us|ns|[fFlLuU]*)$')


@dataclass
class Token:
    """One token, its place read once (libclang asks again per access)."""

    kind: str          # libclang's TokenKind name
    text: str
    line: int
    column: int
    offset: int


def tokens_of(tu, extent):
    """The tokens of an extent, comments left out."""
    tokens = []
    for token in tu.get_tokens(extent=extent):
        kind = token.kind
        if kind == ci.TokenKind.COMMENT:
            continue
        # (one location: each access of token.location asks libclang again)
        location = token.location
        tokens.append(Token(kind.name, token.spelling, location.line,
                            location.column, location.offset))
    return tokens


def brackets(tokens):
    """{index of an opening or closing bracket: index of its partner}."""
    pairs = {}
    stack = []
    for i, token in enumerate(tokens):
        if token.text in OPENING:
            stack.append(i)
        elif token.text in CLOSING:
            # an unbalanced closing bracket (a macro's) closes nothing
            while stack and tokens[stack[-1]].text != CLOSING[token.text]:
                stack.pop()
            if stack:
                opening = stack.pop()
                pairs[opening] = i
                pairs[i] = opening
    return pairs


def joined_text(tokens):
    """Tokens joined as written, readably (a blank between two words)."""
    text = ''
    for token in tokens:
        if text and (text[-1].isalnum() or text[-1] == '_') and \
                (token.text[0].isalnum() or token.text[0] == '_'):
            text += ' '
        text += token.text
    return text


def string_literal(tokens):
    """The value of an argument that is string literals only, or None."""
    if not tokens or any(t.kind != 'LITERAL' or '"' not in t.text
                         for t in tokens):
        return None
    return ''.join(unquote(t.text) for t in tokens)


def seconds_of(tokens):
    """Seconds of a constant period written in tokens, or None.

    Numbers and the four operations; a chrono literal (``100ms``); a
    duration type around them (``std::chrono::milliseconds(100)``,
    ``ros::Duration(0.1)``, ``Duration::from_seconds(0.5)``); a name the
    tokens cannot value makes the period unknown.
    """
    texts = [t.text for t in tokens]
    scale = 1.0
    # Type(args) and Type<...>(args): the unit of the outermost duration
    for i, text in enumerate(texts):
        if text == '(' and i > 0:
            name = texts[i - 1]
            if name == '>':
                depth = 0
                for j in range(i - 1, -1, -1):
                    depth += {'>': 1, '<': -1}.get(texts[j], 0)
                    if depth == 0:
                        name = texts[j - 1] if j else ''
                        break
            if name in _DURATION_TYPES:
                scale = _DURATION_TYPES[name]
                closing = _matching(texts, i)
                if closing is None:
                    return None
                inner = texts[i + 1:closing]
                # Duration(sec, nanosec)
                if name in ('Duration', 'WallDuration') and ',' in inner:
                    comma = inner.index(',')
                    whole = arithmetic(inner[:comma])
                    nanos = arithmetic(inner[comma + 1:])
                    return None if whole is None or nanos is None \
                        else whole + nanos * 1e-9
                value = arithmetic(inner)
                return None if value is None else value * scale
            break
    return arithmetic(texts)


def _matching(texts, opening):
    depth = 0
    for i in range(opening, len(texts)):
        depth += {'(': 1, ')': -1}.get(texts[i], 0)
        if depth == 0:
            return i
    return None


def arithmetic(texts):
    """Value of numbers joined by + - * / and parentheses, or None."""
    position = 0

    def number():
        nonlocal position
        if position >= len(texts):
            raise ValueError
        text = texts[position]
        if text == '(':
            position += 1
            value = expression()
            if position >= len(texts) or texts[position] != ')':
                raise ValueError
            position += 1
            return value
        if text in ('-', '+'):
            position += 1
            value = number()
            return -value if text == '-' else value
        match = _NUMBER.match(text)
        if not match:
            raise ValueError
        position += 1
        value = float(match.group(1))
        return value * _CHRONO_SUFFIX.get(match.group(2), 1.0)

    def term():
        nonlocal position
        value = number()
        while position < len(texts) and texts[position] in ('*', '/'):
            operator = texts[position]
            position += 1
            right = number()
            if operator == '/' and right == 0:
                raise ValueError
            value = value * right if operator == '*' else value / right
        return value

    def expression():
        nonlocal position
        value = term()
        while position < len(texts) and texts[position] in ('+', '-'):
            operator = texts[position]
            position += 1
            right = term()
            value = value + right if operator == '+' else value - right
        return value
    try:
        value = expression()
    except ValueError:
        return None
    return value if position == len(texts) else None
