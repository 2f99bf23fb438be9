# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Edits of the package's code, in memory, for errors no declaration fixes.

Some errors of the model's parse come from its catch-all types themselves,
where C++ asks for one exact type:

- a lambda without a declared result whose returns give a catch-all
  (``rsia_model::Any``) in one branch and a ``double`` in another;
- ``auto *p = image.ptr<T>(row)``, where the catch-all is no pointer;
- ``constexpr double v = deg2rad(40.0)``, where the repaired function
  cannot be constant;
- ``const auto & [id, path] = any``, where the catch-all decomposes into no
  names.

The real build has the real types and none of these errors. So the unit is
parsed again with the line edited in memory (libclang's unsaved files,
never on disk): the lambda returns an ``rsia_model::AnyValue``, the
``auto *`` becomes an ``auto``, the ``constexpr`` a ``const``, the binding's
initializer becomes a value of as many names (see message.h's ``Bound``).
An edit changes the text of one line only, so every fact keeps its file
and line.

An edit is kept in the unit's repair header like a declaration, as
``(kind, "file:line:column")`` with the position in the file as it is on
disk, and checked against the file's text each time it is applied: when
the file changed, an edit whose text is no longer there is dropped.
"""

import re

from colcon_rsia.frontend.cpp.model_mode.source_names import COMMENT_OR_STRING

# the kinds of edit, as repair headers name them
LAMBDA_RESULT = 'edit-lambda-result'  # `-> AnyValue` before a lambda's body
AUTO_POINTER = 'edit-auto-pointer'    # the `*` of `auto *p` blanked
CONSTEXPR = 'edit-constexpr'          # `constexpr` made `const`
BINDING = 'edit-binding'              # `[a, b] = Bound<2>() <<= any`
EDIT_KINDS = (LAMBDA_RESULT, AUTO_POINTER, CONSTEXPR, BINDING)

# a type in a message, with what its alias names: 'value_type' (aka 'double')
_TYPE = r"'.*'(?: \(aka '.*'\))?"
_LAMBDA_RESULT_ERROR = re.compile(
    f'^return type {_TYPE} must match previous return type {_TYPE} '
    'when lambda expression has unspecified explicit return type$')
_AUTO_POINTER_ERROR = re.compile(
    r"^variable '\w+' with type '(?:const )?auto \*(?: ?const)?' has "
    r"incompatible initializer of type '(?:::)?rsia_model::\w+'$")
_CONSTEXPR_ERROR = re.compile(
    r"^constexpr variable '\w+' must be initialized by a constant "
    r'expression$|^constexpr variable cannot have non-literal type ')
_BINDING_ERROR = re.compile(
    r"^type '.*' decomposes into \d+ elements?, but \d+ names were "
    r'provided$|^cannot decompose ')

_RESULT = '-> ::rsia_model::AnyValue '
# how far before a `return` its lambda's body may open
_SCAN_LIMIT = 20000
# the words that end a statement's head before a block (`if (...) {`,
# `if constexpr (...) {`)
_BLOCK_HEADS = frozenset(('if', 'for', 'while', 'switch', 'catch', 'constexpr'))
# the words a lambda may follow
_BEFORE_LAMBDA = frozenset(('return', 'co_return', 'co_yield', 'case'))
_CONSTEXPR_WORD = re.compile(r'\bconstexpr\b')
_AUTO_POINTER = re.compile(r'\bauto\s*(\*)\s*(?:const\s*)?$')


def edits_from_diagnostics(diagnostics, read_code):
    """{(kind, "file:line:column")}: the edits that would fix these errors.

    :param diagnostics: (message, file, line, column) of the errors in the
      workspace's files, their columns on disk (see :func:`disk_column`)
    :param read_code: returns a file's text on disk, read as latin-1 (one
      character per byte, as clang counts columns), or None
    """
    edits = set()
    masked_code = {}
    for message, file, line, column in diagnostics:
        kind = _kind_of(message)
        if kind is None or not file or ' ' in file:
            continue  # (a repair header's entry is one word)
        if file not in masked_code:
            code = read_code(file)
            masked_code[file] = None if code is None else _masked(code)
        masked = masked_code[file]
        offset = None if masked is None else _offset(masked, line, column)
        if offset is None:
            continue
        anchor = {
            LAMBDA_RESULT: _lambda_body,
            AUTO_POINTER: _pointer_star,
            CONSTEXPR: _constexpr_keyword,
            BINDING: _binding_names,
        }[kind](masked, offset)
        if anchor is not None:
            at_line, at_column = _position(masked, anchor)
            edits.add((kind, f'{file}:{at_line}:{at_column}'))
    return edits


def _kind_of(message):
    for kind, pattern in ((LAMBDA_RESULT, _LAMBDA_RESULT_ERROR),
                          (AUTO_POINTER, _AUTO_POINTER_ERROR),
                          (CONSTEXPR, _CONSTEXPR_ERROR),
                          (BINDING, _BINDING_ERROR)):
        if pattern.match(message):
            return kind
    return None


def edited_files(edits, read_code):
    """{file: (edited bytes, {line: [(disk column, inserted length)]})}.

    :param edits: (kind, "file:line:column") pairs, of any repair kinds
      (the others are left out)
    :param read_code: as for :func:`edits_from_diagnostics`
    """
    by_file = {}
    for kind, name in edits:
        if kind not in EDIT_KINDS:
            continue
        file, line, column = name.rsplit(':', 2)
        by_file.setdefault(file, set()).add((kind, int(line), int(column)))
    result = {}
    for file, positions in sorted(by_file.items()):
        code = read_code(file)
        if code is None:
            continue
        masked = _masked(code)
        changes = set()  # (offset, characters replaced, replacement)
        for kind, line, column in sorted(positions):
            offset = _offset(masked, line, column)
            change = None if offset is None else \
                _change(kind, masked, offset)
            if change is not None:
                changes.add(change)
        if not changes:
            continue
        insertions = {}
        for offset, replaced, replacement in sorted(changes, reverse=True):
            code = code[:offset] + replacement + code[offset + replaced:]
            if len(replacement) != replaced:
                line, column = _position(masked, offset)
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


def _change(kind, masked, offset):
    """(offset, characters replaced, replacement) of the edit at offset.

    None if the code there is not what the edit was made for.
    """
    if kind == LAMBDA_RESULT:
        if masked[offset] != '{' or _lambda_kind(masked, offset) is None:
            return None
        has_parameters = _lambda_kind(masked, offset)
        return offset, 0, _RESULT if has_parameters else '() ' + _RESULT
    if kind == AUTO_POINTER:
        return (offset, 1, ' ') if masked[offset] == '*' else None
    if kind == BINDING:
        return _bound_initializer(masked, offset)
    if masked.startswith('constexpr', offset):
        # in a class, a static member keeps an initializer of any type
        # only as an inline variable; elsewhere a `const` takes any
        static = _word_before(masked, offset) == 'static'
        return offset, len('constexpr'), \
            'inline   ' if static else 'const    '
    return None


def _bound_initializer(masked, names):
    """The insertion that gives the binding `[...]` at `names` a Bound."""
    if masked[names] != '[':
        return None
    end = _matching_close(masked, names, '[', ']')
    if end is None:
        return None
    count = _top_level_commas(masked, names + 1, end) + 1
    after = end + 1
    while after < len(masked) and masked[after].isspace():
        after += 1
    follows = masked[after:after + 2]
    if follows[:1] in ('=', '(', '{') and follows != '==':
        return after + 1, 0, f' ::rsia_model::Bound<{count}>() <<= '
    if follows[:1] == ':' and follows != '::':
        return after + 1, 0, f' ::rsia_model::BoundEach<{count}>() <<= '
    return None


def _binding_names(masked, offset):
    """Offset of the `[` of a structured binding clang reported."""
    line_end = masked.find('\n', offset)
    names = masked.find('[', offset, None if line_end < 0 else line_end)
    return None if names < 0 else names


def _lambda_body(masked, offset):
    """Offset of the `{` opening the innermost lambda around a `return`."""
    depth = 0
    for i in range(offset - 1, max(-1, offset - _SCAN_LIMIT), -1):
        character = masked[i]
        if character == '}':
            depth += 1
        elif character == '{':
            if depth:
                depth -= 1
                continue
            opened = _opened_by(masked, i)
            if opened == 'lambda':
                return i
            if opened != 'block':
                return None
    return None


def _opened_by(masked, brace):
    """What a `{` opens: 'lambda', 'block' (of a statement) or 'other'."""
    if _lambda_kind(masked, brace) is not None:
        return 'lambda'
    end = _end_before(masked, brace)
    if masked[end - 1:end] == ')':
        opening = _matching_open(masked, end - 1, '(', ')')
        if opening is not None and \
                _word_before(masked, opening) in _BLOCK_HEADS:
            return 'block'
        return 'other'  # a function's body: no lambda is around it
    return 'block'  # `else {`, `do {`, `{` alone, `case x: {`


def _lambda_kind(masked, brace):
    """For a lambda's body `{`: whether it has parameters; else None."""
    end = _end_before(masked, brace)
    # `mutable`, `noexcept` and the like between
    while _word_before(masked, end) in (
            'mutable', 'noexcept', 'constexpr', 'consteval'):
        end = _end_before(masked, end - len(_word_before(masked, end)))
    has_parameters = masked[end - 1:end] == ')'
    if has_parameters:
        opening = _matching_open(masked, end - 1, '(', ')')
        if opening is None:
            return None
        end = _end_before(masked, opening)
    if masked[end - 1:end] != ']':
        return None
    introducer = _matching_open(masked, end - 1, '[', ']')
    if introducer is None:
        return None
    # `a[i] {` subscripts; a lambda follows an operator, `(`, `,`, `=` or
    # a word such as `return`
    word = _word_before(masked, introducer)
    if word and word not in _BEFORE_LAMBDA:
        return None
    before = _end_before(masked, introducer)
    if masked[before - 1:before] in (')', ']'):
        return None
    return has_parameters


def _pointer_star(masked, offset):
    """Offset of the `*` of `auto *name` (`name` at offset)."""
    match = _AUTO_POINTER.search(masked, max(0, offset - 200), offset)
    return match.start(1) if match else None


def _constexpr_keyword(masked, offset):
    """Offset of the `constexpr` declaring the variable at offset."""
    start = masked.rfind(';', 0, offset)
    start = max(start, masked.rfind('{', 0, offset),
                masked.rfind('}', 0, offset))
    keywords = list(_CONSTEXPR_WORD.finditer(masked, start + 1, offset))
    return keywords[-1].start() if keywords else None


def _matching_close(masked, opening, open_character, close_character):
    depth = 0
    for i in range(opening, min(len(masked), opening + _SCAN_LIMIT)):
        if masked[i] == open_character:
            depth += 1
        elif masked[i] == close_character:
            depth -= 1
            if depth == 0:
                return i
    return None


def _top_level_commas(masked, start, end):
    depth = 0
    commas = 0
    for character in masked[start:end]:
        if character in '([{<':
            depth += 1
        elif character in ')]}>':
            depth -= 1
        elif character == ',' and depth == 0:
            commas += 1
    return commas


def _matching_open(masked, closing, open_character, close_character):
    depth = 0
    for i in range(closing, max(-1, closing - _SCAN_LIMIT), -1):
        if masked[i] == close_character:
            depth += 1
        elif masked[i] == open_character:
            depth -= 1
            if depth == 0:
                return i
    return None


def _end_before(masked, offset):
    """The end of the code before offset, white space left out."""
    while offset > 0 and masked[offset - 1].isspace():
        offset -= 1
    return offset


def _word_before(masked, offset):
    """The word that ends right before offset (white space between), or ''."""
    end = _end_before(masked, offset)
    start = end
    while start > 0 and (masked[start - 1].isalnum() or masked[start - 1] == '_'):
        start -= 1
    return masked[start:end]


def _masked(code):
    """The code with comments and literals blanked (offsets kept)."""
    return COMMENT_OR_STRING.sub(
        lambda m: re.sub(r'[^\n]', ' ', m.group(0)), code)


def _offset(code, line, column):
    """Offset of a 1-based line and (byte) column, if inside the line."""
    start = 0
    for _ in range(line - 1):
        start = code.find('\n', start) + 1
        if start == 0:
            return None
    end = code.find('\n', start)
    end = len(code) if end < 0 else end
    offset = start + column - 1
    return offset if start <= offset < end or (offset == end and column == 1) \
        else None


def _position(code, offset):
    line = code.count('\n', 0, offset) + 1
    return line, offset - (code.rfind('\n', 0, offset) + 1) + 1
