# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Edits applied to the code in memory, lines and columns kept."""

import re
from urllib.parse import unquote

from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import arguments_of_call
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import end_of_argument
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import lambda_kind
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import masked_code
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import matching
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import offset_of
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import operands
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import position_of
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import top_level_commas
from colcon_rsia.frontend.cpp.model_mode.recovery.edit_text import word_before
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import _assignment
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import ADDRESS
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import AS
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import ASSIGNED
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import AUTO_POINTER
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import BINDING
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import CAST
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import CAST_KEYWORDS
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import CONSTEXPR
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import INDEX
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import LAMBDA_RESULT
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import MEMBER_POINTER
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import MOVE_ONLY
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import OPERAND
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import RANGE_REFERENCE
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import RESULT
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import STRING
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import is_edit


def edited_files(edits, read_code):
    """{file: (edited bytes, {line: [(disk column, inserted length)]})}.

    :param edits: (kind, "file:line:column") pairs, of any repair kinds
      (the others are left out)
    :param read_code: as for :func:`edits_from_diagnostics`
    """
    by_file = {}
    for kind, name in edits:
        if not is_edit(kind):
            continue
        file, line, column = name.rsplit(':', 2)
        by_file.setdefault(file, set()).add((kind, int(line), int(column)))
    result = {}
    for file, positions in sorted(by_file.items()):
        code = read_code(file)
        if code is None:
            continue
        masked = masked_code(code)
        changes = set()  # (offset, characters replaced, replacement)
        for kind, line, column in sorted(positions):
            offset = offset_of(masked, line, column)
            if offset is not None:
                changes.update(edit_changes(kind, masked, offset))
        if not changes:
            continue
        insertions = {}
        for offset, replaced, replacement in sorted(changes, reverse=True):
            code = code[:offset] + replacement + code[offset + replaced:]
            if len(replacement) != replaced:
                line, column = position_of(masked, offset)
                insertions.setdefault(line, []).append(
                    (column, len(replacement) - replaced))
        result[file] = (code.encode('latin-1'),
                        {line: sorted(shifts)
                         for line, shifts in insertions.items()})
    return result


def disk_column(insertions, line, column):
    """The column on disk of a column of the edited text's `line`.

    :param insertions: what :func:`edited_files` gives for the file, or {}
    """
    shift = 0
    for at, length in insertions.get(line, ()):
        if column <= at + shift:
            break
        shift += length
    return max(1, column - shift)


def edited_column(insertions, line, column):
    """The column in the edited text of a column on disk (see above)."""
    return column + sum(length for at, length in insertions.get(line, ())
                        if at <= column)


def edit_changes(kind, masked, offset):
    """[(offset, characters replaced, replacement)] of the edit at offset.

    None when the code there is not what the edit was made for.
    """
    kind, _, detail = kind.partition(':')
    if kind == CAST:
        return casts(masked, offset, unquote(detail).split(';'))
    if kind == AS:
        end = end_of_argument(masked, offset)
        made = unquote(detail)
        # (a std::unique_ptr is moved from, never copied: an rvalue)
        function = 'assigned_as' if MOVE_ONLY.match(made) else 'as'
        return [] if end is None else [
            (offset, 0, f'::rsia_model::{function}<{made}>('), (end, 0, ')')]
    if kind == ASSIGNED:
        assignment = _assignment(masked, offset)
        if assignment is None:
            return []
        target, value, end = assignment
        return [(value, 0,
                 f'::rsia_model::assigned_as<decltype({target})>('),
                (end, 0, ')')]
    change = None
    if kind == LAMBDA_RESULT:
        if masked[offset] == '{' and \
                lambda_kind(masked, offset) is not None:
            has_parameters = lambda_kind(masked, offset)
            change = offset, 0, \
                RESULT if has_parameters else '() ' + RESULT
    elif kind in (AUTO_POINTER, ADDRESS, RANGE_REFERENCE):
        blanked = '*' if kind == AUTO_POINTER else '&'
        if masked[offset] == blanked and \
                masked[offset + 1:offset + 2] != blanked:
            change = offset, 1, ' '
    elif kind == BINDING:
        change = bound_initializer(masked, offset)
    elif kind == MEMBER_POINTER and masked.startswith(('.*', '->*'), offset):
        # the object and its `.`/`->` blanked, the `*` kept
        star = masked.index('*', offset)
        start = offset
        while start > 0 and re.match(r'[\w.:>\-\[\]]', masked[start - 1]):
            start -= 1
        if start < offset:
            change = start, star - start, ' ' * (star - start)
    elif kind == INDEX:
        close = matching(masked, offset) if masked[offset] == '[' else None
        return [] if close is None else [
            (offset + 1, 0, '::rsia_model::as<long>('), (close, 0, ')')]
    elif kind == OPERAND:
        which, _, type_name = detail.partition(':')
        type_name = unquote(type_name)
        spans = operands(masked, offset)
        if spans is None:
            return []
        start, end = spans[int(which) - 2]
        # (only a literal is blank once literals are masked)
        if (not masked[start:end].strip()) != (type_name == STRING):
            return []
        return [(start, 0, f' ::rsia_model::as<{type_name}>('), (end, 0, ')')]
    elif kind in CAST_KEYWORDS and \
            masked.startswith(CAST_KEYWORDS[kind][0], offset):
        # (a cast between classes that know no bases of each other; a
        # value made the pointer wanted, see message.h's `as`)
        keyword, replacement = CAST_KEYWORDS[kind]
        change = offset, len(keyword), replacement
    elif kind == CONSTEXPR and masked.startswith('constexpr', offset):
        # in a class, a static member keeps an initializer of any type
        # only as an inline variable; elsewhere a `static const` takes any,
        # and a lambda uses it uncaptured, as it would the constant
        static = word_before(masked, offset) == 'static'
        change = offset, len('constexpr'), \
            'inline   ' if static else 'static const'
    return [] if change is None else [change]


def casts(masked, callee, types):
    """The insertions that cast a call's arguments to `types`.

    A braced argument (`{lane}`) has no type to cast: it is made a
    temporary of the parameter's class (`std::vector<Lanelet>{lane}`),
    unless the parameter is a reference to a class to change.
    """
    arguments = arguments_of_call(masked, callee)
    if arguments is None or len(arguments) > len(types):
        return []
    changes = []
    for (start, end), parameter in zip(arguments, types):
        if masked[start] == '{':
            if not re.search(r'(?<!&)&$', parameter) or \
                    parameter.startswith('const '):
                changes.append((start, 0, re.sub(
                    r'^const\s+|\s*&+$', '', parameter)))
        else:
            # (no static_cast: a catch-all converts to a class that has
            # constructors of its own, `const_iterator`, more ways than one)
            made = 'assigned_as' if parameter.endswith('&&') else 'as'
            changes += [(start, 0, f'::rsia_model::{made}<{parameter}>('),
                        (end, 0, ')')]
    return changes


def bound_initializer(masked, names):
    """The insertion that gives the binding `[...]` at `names` a Bound."""
    if masked[names] != '[':
        return None
    end = matching(masked, names)
    if end is None:
        return None
    count = top_level_commas(masked, names + 1, end) + 1
    after = end + 1
    while after < len(masked) and masked[after].isspace():
        after += 1
    follows = masked[after:after + 2]
    if follows[:1] in ('=', '(', '{') and follows != '==':
        return after + 1, 0, f' ::rsia_model::Bound<{count}>() <<= '
    if follows[:1] == ':' and follows != '::':
        return after + 1, 0, f' ::rsia_model::BoundEach<{count}>() <<= '
    return None
