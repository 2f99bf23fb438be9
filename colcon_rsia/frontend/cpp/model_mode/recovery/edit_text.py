# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Reading code for edits: masked text, offsets, brackets, arguments."""

import re

from colcon_rsia.frontend.cpp.model_mode.source_names import COMMENT_OR_STRING
from colcon_rsia.frontend.cpp.model_mode.source_names import \
    end_of_template_arguments

# the callee of a call, from where clang reports it: a (qualified) name,
# its template arguments after it
CALLEE = re.compile(r'(?:::)?\s*~?[A-Za-z_]\w*(?:\s*::\s*~?[A-Za-z_]\w*)*\s*')
# where a variable's initializer takes an address (`data = &msg.data[0]`)
INITIALIZED_ADDRESS = re.compile(r'\w+\s*(?:=|\(|\{)\s*(&)(?!&)')
# how far before a `return` its lambda's body may open
SCAN_LIMIT = 20000
# the words that end a statement's head before a block (`if (...) {`,
# `if constexpr (...) {`)
BLOCK_HEADS = frozenset(('if', 'for', 'while', 'switch', 'catch', 'constexpr'))
# the words a lambda may follow
BEFORE_LAMBDA = frozenset(('return', 'co_return', 'co_yield', 'case'))
CONSTEXPR_WORD = re.compile(r'\bconstexpr\b')
AUTO_POINTER_SPELLING = re.compile(r'\bauto\s*(\*)\s*(?:const\s*)?$')


def end_of_argument(masked, start):
    """The end of the argument or initializer that starts at start.

    Before the `,`, `)` or `;` that ends it; None when a block (a `;`
    inside brackets) comes first.
    """
    if masked[start].isspace() or masked[start] in ',)':
        return None
    ending = expression_end(masked, start)
    if ending is None:
        return None
    end, inner_statement = ending
    if inner_statement or masked[end] in ']}':
        return None
    return end_before(masked, end)


def expression_end(masked, start):
    """(offset, inner statement) of what ends the expression at start.

    The offset of the first `,` or `;` at the expression's own level, or
    of the bracket that closes around it; whether a `;` inside brackets
    (a lambda's body) came before it. None past the scan's limit.
    """
    depth = 0
    inner_statement = False
    skip_to = start
    for i in range(start, min(len(masked), start + SCAN_LIMIT)):
        if i < skip_to:
            continue
        character = masked[i]
        if character == '<' and i > start and \
                (masked[i - 1].isalnum() or masked[i - 1] == '_'):
            # template arguments, written against the name (`T<A, 1>`;
            # a comparison has spaces): their commas end nothing
            skip_to = end_of_template_arguments(masked, i) or i
        elif character in '([{':
            depth += 1
        elif character in ')]}':
            if depth == 0:
                return i, inner_statement
            depth -= 1
        elif character in ',;' and depth == 0:
            return i, inner_statement
        elif character == ';':
            inner_statement = True
    return None


def arguments_of_call(masked, callee):
    """[(start, end)] of the arguments of the call of the callee there."""
    name = CALLEE.match(masked, callee)
    if name is None:
        return None
    opening = end_of_template_arguments(masked, name.end()) or name.end()
    while opening < len(masked) and masked[opening].isspace():
        opening += 1
    if masked[opening:opening + 1] != '(':
        return None
    return arguments_at(masked, opening)


def arguments_at(masked, opening):
    """[(start, end)] of the arguments of the call whose `(` is at opening.

    A literal, blank in the masked code, keeps its place (its span blank):
    the arguments after it keep their indexes.
    """
    closing = matching(masked, opening)
    if closing is None:
        return None
    spans = []
    start = opening + 1
    depth = 0
    for i in range(opening + 1, closing + 1):
        character = masked[i]
        if character in '([{':
            depth += 1
        elif character in ')]}' and i < closing:
            depth -= 1
        elif character == ',' and depth == 0 or i == closing:
            first = end_before(masked, i)  # (the argument's end)
            begin = start
            while begin < first and masked[begin].isspace():
                begin += 1
            if begin < first:
                spans.append((begin, first))
            elif i - start >= 2:  # (`"name"`: blank, two quotes at least)
                spans.append((start, i))
            start = i + 1
    return spans


def operands(masked, question):
    """[(start, end)] of the second and third operands of a `?`, or None.

    Each with the white space around it.
    """
    if masked[question] != '?':
        return None
    colon = conditional_colon(masked, question)
    ending = None if colon is None else expression_end(masked, colon + 1)
    if ending is None:
        return None
    return [(question + 1, colon), (colon + 1, ending[0])]


def conditional_colon(masked, question):
    """Offset of the `:` pairing with the `?` at question, or None."""
    depth = 0
    nested = 0
    for i in range(question + 1, min(len(masked), question + SCAN_LIMIT)):
        character = masked[i]
        if character in '([{':
            depth += 1
        elif character in ')]};' and depth == 0:
            return None
        elif character in ')]}':
            depth -= 1
        elif depth == 0 and character == '?':
            nested += 1
        elif depth == 0 and character == ':':
            if masked[i + 1:i + 2] == ':' or masked[i - 1] == ':':
                continue  # a scope's `::`
            if not nested:
                return i
            nested -= 1
    return None


def address_of(masked, offset):
    """Offset of the `&` taking an address clang reported.

    At the argument (a parameter's), or at the variable's name.
    """
    if masked[offset] == '&':
        return offset if masked[offset + 1:offset + 2] != '&' else None
    match = INITIALIZED_ADDRESS.match(masked, offset)
    return match.start(1) if match else None


def range_reference(masked, offset):
    """Offset of the `&` of the range-for variable named at offset."""
    if not re.match(r'[A-Za-z_]\w*\s*:(?!:)', masked[offset:offset + 200]):
        return None
    before = masked[:offset].rstrip()
    if not before.endswith('&') or before.endswith('&&'):
        return None
    ampersand = len(before) - 1
    head = masked[statement_start(masked, ampersand):ampersand]
    return ampersand if re.search(r'\bfor\s*\([^;()]*$', head) else None


def binding_names(masked, offset):
    """Offset of the `[` of a structured binding clang reported."""
    line_end = masked.find('\n', offset)
    names = masked.find('[', offset, None if line_end < 0 else line_end)
    return None if names < 0 else names


def lambda_body(masked, offset):
    """Offset of the `{` opening the innermost lambda around a `return`."""
    depth = 0
    for i in range(offset - 1, max(-1, offset - SCAN_LIMIT), -1):
        character = masked[i]
        if character == '}':
            depth += 1
        elif character == '{':
            if depth:
                depth -= 1
                continue
            opened = opened_by(masked, i)
            if opened == 'lambda':
                return i
            if opened != 'block':
                return None
    return None


def opened_by(masked, brace):
    """What a `{` opens: 'lambda', 'block' (of a statement) or 'other'."""
    if lambda_kind(masked, brace) is not None:
        return 'lambda'
    end = end_before(masked, brace)
    if masked[end - 1:end] == ')':
        opening = matching(masked, end - 1)
        if opening is not None and \
                word_before(masked, opening) in BLOCK_HEADS:
            return 'block'
        return 'other'  # a function's body: no lambda is around it
    return 'block'  # `else {`, `do {`, `{` alone, `case x: {`


def lambda_kind(masked, brace):
    """For a lambda's body `{`: whether it has parameters; else None."""
    end = end_before(masked, brace)
    # `mutable`, `noexcept` and the like between
    while word_before(masked, end) in (
            'mutable', 'noexcept', 'constexpr', 'consteval'):
        end = end_before(masked, end - len(word_before(masked, end)))
    has_parameters = masked[end - 1:end] == ')'
    if has_parameters:
        opening = matching(masked, end - 1)
        if opening is None:
            return None
        end = end_before(masked, opening)
    if masked[end - 1:end] != ']':
        return None
    introducer = matching(masked, end - 1)
    if introducer is None:
        return None
    # `a[i] {` subscripts; a lambda follows an operator, `(`, `,`, `=` or
    # a word such as `return`
    word = word_before(masked, introducer)
    if word and word not in BEFORE_LAMBDA:
        return None
    before = end_before(masked, introducer)
    if masked[before - 1:before] in (')', ']'):
        return None
    return has_parameters


def pointer_star(masked, offset):
    """Offset of the `*` of `auto *name` (`name` at offset)."""
    match = AUTO_POINTER_SPELLING.search(masked, max(0, offset - 200), offset)
    return match.start(1) if match else None


def constexpr_keyword(masked, offset):
    """Offset of the `constexpr` declaring the variable at offset."""
    keywords = list(CONSTEXPR_WORD.finditer(
        masked, statement_start(masked, offset), offset))
    return keywords[-1].start() if keywords else None


def statement_start(masked, offset):
    """Where the statement around offset begins (after `;`, `{` or `}`)."""
    return max(masked.rfind(c, 0, offset) for c in ';{}') + 1


# where each edit of edits_from_diagnostics goes, from where clang reports
# its error (the operand's edit is placed by operand_edit)

PAIRED = {'(': ')', '[': ']', '{': '}', ')': '(', ']': '[', '}': '{'}


def matching(masked, at):
    """Offset of the bracket that pairs with the one at `at`, or None.

    Forward from an opening bracket, backward from a closing one.
    """
    own = masked[at]
    other = PAIRED[own]
    step = 1 if own in '([{' else -1
    depth = 0
    for i in range(at, max(-1, min(len(masked), at + step * SCAN_LIMIT)),
                   step):
        if masked[i] == own:
            depth += 1
        elif masked[i] == other:
            depth -= 1
            if depth == 0:
                return i
    return None


def top_level_commas(masked, start, end):
    """How many commas between start and end are outside brackets."""
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


def end_before(masked, offset):
    """The end of the code before offset, white space left out."""
    while offset > 0 and masked[offset - 1].isspace():
        offset -= 1
    return offset


def word_before(masked, offset):
    """The word that ends right before offset (white space between), or ''."""
    end = end_before(masked, offset)
    start = end
    while start > 0 and (masked[start - 1].isalnum() or masked[start - 1] == '_'):
        start -= 1
    return masked[start:end]


def masked_reader(read_code):
    """A file's masked code (see :func:`masked_code`), masked once a file."""
    masked = {}

    def masked_of(file):
        if file not in masked:
            code = read_code(file)
            masked[file] = None if code is None else masked_code(code)
        return masked[file]
    return masked_of


def masked_code(code):
    """The code with comments and literals blanked (offsets kept)."""
    return COMMENT_OR_STRING.sub(
        lambda m: re.sub(r'[^\n]', ' ', m.group(0)), code)


def offset_of(code, line, column):
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


def position_of(code, offset):
    """(line, column) of an offset, as clang counts them."""
    line = code.count('\n', 0, offset) + 1
    return line, offset - (code.rfind('\n', 0, offset) + 1) + 1
