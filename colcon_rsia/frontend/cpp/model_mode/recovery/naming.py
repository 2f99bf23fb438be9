# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""How a name is used decides what a repair declares it as."""

import re

from colcon_rsia.frontend.cpp.model_mode.model_index import declared_names
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import ALL_CAPS
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import base_kind
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import C_FUNCTION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import CAMEL
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import CONSTANT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import declared_as_variable
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import FUNCTION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import K_CONSTANT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import KEYWORDS
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import LOWER_CAMEL
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MACRO_VALUE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_TYPE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NAMESPACE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import OBJECT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import opened_namespaces
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import SOURCE_NOISE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TYPE
from colcon_rsia.frontend.cpp.model_mode.source_names import end_of_template_arguments
from colcon_rsia.frontend.cpp.model_mode.source_names import template_arguments
from colcon_rsia.frontend.cpp.model_mode.source_names import template_kind


def uses_of_namespace(namespace, texts, aliases=None, depth=0):
    """(kind, name) of what the texts use after ``namespace::``.

    Also after an alias of it (`bg::` for boost::geometry), and in the
    namespaces used inside it (`bg::model::d2::point_xy<double>`), each of
    which clang would report only once the one around it exists: a parse
    saved per level.
    """
    spellings = [namespace] + [
        alias + namespace[len(target):]
        for alias, target in (aliases or {}).items()
        if namespace == target or namespace.startswith(target + '::')]
    pattern = re.compile(
        '(?<![\\w:])(?:' + '|'.join(
            re.escape(spelling).replace('::', r'\s*::\s*')
            for spelling in spellings) +
        r')\s*::\s*(\w+)(?:\s*::\s*(\w+))?(?=(\s*[^\n]{0,200}))')
    found = set()
    inner = set()
    for text in texts:
        for match in pattern.finditer(text):
            name, member, after = match.groups()
            if name in KEYWORDS or name == 'template':
                continue
            rest = after.lstrip()
            kind = by_qualified_use(
                name, '::' if member else rest,
                text[max(0, match.start() - 200):match.start()], texts)
            if base_kind(kind) == TEMPLATE and not member and \
                    rest.startswith('<'):
                # arguments that go on past the line (`rotate_transformer<`
                # then `bg::radian, double, 2, 2>`) still have a shape
                kind = template_shape(' '.join(
                    text[match.start(3):match.start(3) + 400].split()), texts)
            found.add((kind, f'{namespace}::{name}'))
            if kind == NAMESPACE:
                inner.add(f'{namespace}::{name}')
            if member and kind == TYPE and member not in KEYWORDS:
                nested = by_use(member, rest, unqualified=False)[0] == TYPE \
                    and names_nested_type(rest, text[
                        max(0, match.start() - 200):match.start()])
                # (`Converter::toImage<uint16_t, 1>(...)`: a template)
                found.add((
                    MEMBER_TYPE if nested else MEMBER_TEMPLATE
                    if re.match(r'<(?![<=])', rest) else MEMBER,
                    f'{namespace}::{name}::{member}'))
    if depth < 3:
        for name in sorted(inner):
            found |= uses_of_namespace(name, texts, aliases, depth + 1)
    return found


def names_nested_type(after, before):
    """Whether `Owner::Member`, between these, is a type of the class.

    So is one that declares a variable (`ns::Grid::Ptr grid`), one among
    template arguments (`std::optional<Buffer::Result>`) and one made of
    braces (`Trajectory<P>::Builder{}.build(points)`).
    """
    return bool(re.match(r'(?:[&*]\s*)?[A-Za-z_]|\{', after)) or (
        after.startswith(('>', ',')) and in_template_arguments(before))


def namespace_at(read_line, file, line):
    """The named namespaces open at a line of a file (`a::b`), or ''."""
    return '::'.join(opened_namespaces(SOURCE_NOISE.sub(' ', '\n'.join(
        read_line(file, number) for number in range(1, line)))))


# the first quoted name of a message: 'cudaMemcpyHostToDevice' of "use of
# undeclared identifier 'cudaMemcpyHostToDevice'"
QUOTED_NAME = re.compile(r"'(\w+)'")
# how many lines past its first the arguments of a macro's call may go on
_MACRO_CALL_LINES = 12


def in_macro_arguments(read_line, file, line, text, column, name):
    """(text, column) of the line that spells the name a message is about.

    Of a name in the arguments of a macro's call, clang gives the line the
    call starts on: `CHECK_CUDA_ERROR(cudaMemcpy(` with the name on one of
    the lines that follow, inside the call's parentheses.
    """
    spelled = re.compile(r'\b' + name + r'\b')
    if spelled.search(text):
        return text, column
    depth = text[max(0, column - 1):].count('(') - \
        text[max(0, column - 1):].count(')')
    for number in range(line + 1, line + 1 + _MACRO_CALL_LINES):
        if depth <= 0:
            break
        following = read_line(file, number)
        found = spelled.search(following)
        if found:
            return following, found.start() + 1
        depth += following.count('(') - following.count(')')
    return text, column


def qualified(name, text, column):
    """`ns::Name` when the line qualifies the name clang calls unknown."""
    before = text[:max(0, column - 1)]
    match = re.search(r'((?:[A-Za-z_]\w*\s*::\s*)+)$', before)
    if not match:
        return name
    scopes = re.sub(r'\s+', '', match.group(1)).split('::')[:-1]
    # (`public ::testing::Test`: a keyword before the global scope)
    while scopes and scopes[0] in KEYWORDS and \
            scopes[0] not in ('std', 'rsia_model'):
        scopes.pop(0)
    return '::'.join(scopes + [name])


def opens_body(read_line, file, line, text, start):
    """Whether a body in braces follows the call whose `(` ends at start.

    (The braces may open the next line, as clang-format puts a function's.)
    """
    depth = 1
    for position in range(start, len(text)):
        depth += {'(': 1, ')': -1}.get(text[position], 0)
        if depth == 0:
            rest = text[position + 1:].strip()
            if not rest and file:
                rest = read_line(file, line + 1).strip()
            return rest.startswith('{')
    return False


def after_name(text, column, name):
    """What follows the name a message is about, on its line."""
    if not text or not name:
        return ''
    start = max(0, column - 1)
    found = text.find(name, start)
    if found < 0:
        found = text.find(name)
    if found < 0:
        return ''
    return text[found + len(name):].lstrip()


def next_line(read_line, file, line, text, name):
    """What follows the name of a message that ends its line.

    `cond ? Qt::ForbiddenCursor` with `: Qt::ArrowCursor` below: what the
    next line starts with tells a value from a type as the rest of the
    name's own line would.
    """
    if not file or not name or not re.search(r'\b' + name + r'\s*$', text):
        return ''
    return read_line(file, line + 1).lstrip()


# a name (@) as the type of a cast: `static_cast<@>(`, `(@)value`
CAST_TYPE = re.compile(r'_cast\s*<\s*@>|(?<![\w\])])\s*\(\s*@\)\s*[\w(]')
# what comes before `ns::name` in `std::pair<ns::name, ...>`
_FIRST_TEMPLATE_ARGUMENT = re.compile(r'\w<\s*(?:::\s*)?(?:\w+\s*::\s*)*$')
# what comes before `Name` in `using ns::Name;`: a CamelCase name a
# using-declaration brings in is a class far more often than an enumerator
_USING_DECLARATION = re.compile(r'\busing\s+(?:::\s*)?(?:\w+\s*::\s*)*$')


def by_qualified_use(name, after, before, texts=()):
    """The kind of ``ns::name`` from the code around it on its line."""
    kind = by_use(name, after, unqualified=False, texts=texts)[0]
    if kind == CONSTANT and CAMEL.match(name) and \
            _USING_DECLARATION.search(before):
        return TYPE
    if kind in (OBJECT, CONSTANT) and _FIRST_TEMPLATE_ARGUMENT.search(before):
        # std::pair<boost::uuids::uuid, T>: a first template argument is a
        # type far more often than a value
        return TYPE
    if kind == OBJECT and after.startswith(('>', ',')) and \
            in_template_arguments(before) and not K_CONSTANT.match(name):
        # model::point<double, 2, bg::cs::cartesian>: a lower-case name
        # among template arguments is a type (a tag), as template_kind
        # takes it; a value would be a constant (kSize, MAX_SIZE)
        return TYPE
    if kind == CONSTANT and after.startswith(',') and \
            in_template_arguments(before):
        # Matrix<float, Eigen::Dynamic, 1>: the template's parameters were
        # made from its use, where a CamelCase name is a type (see
        # template_kind)
        return TYPE
    return kind


def in_template_arguments(before):
    """Whether the code before a name leaves a `<` of a template open."""
    statement = re.split(r'[;{}]', before)[-1]
    statement = re.sub(r'<<|>>|->|<=|>=', ' ', statement)
    return statement.count('<') > statement.count('>')


_CALL = re.compile(r'\s*\(')


def by_use(name, after, *, unqualified, texts=()):
    """(kind, name) of a name from what follows it."""
    if after.startswith('::'):
        # undeclared: a namespace (Eigen::, karto::); a class of the
        # package would be declared (and never repaired); qualified: by
        # convention namespaces are lower case, classes CamelCase
        if CAMEL.match(name) and not ALL_CAPS.match(name) and \
                not unqualified:
            return TYPE, name
        return NAMESPACE, name
    if after.startswith('('):
        if ALL_CAPS.match(name) and unqualified:
            return MACRO_VALUE, name
        return (TYPE if CAMEL.match(name) and not ALL_CAPS.match(name)
                and not C_FUNCTION.match(name) else FUNCTION), name
    if after.startswith('<') and not after.startswith(('<<', '<=')) and \
            not _compares(after):
        return template_use(name, after, unqualified=unqualified,
                            texts=texts), name
    if ALL_CAPS.match(name):
        return CONSTANT, name
    if CAMEL.match(name) and not unqualified and \
            re.match(r'(?:\)|;|,|\||\+|-|=|\?|\]|\}|!|:(?!:)|&&\s*[!(])',
                     after):
        # a CamelCase value, where a value ends or an operator follows: an
        # enumerator (Qt::AlignCenter), a constant (lanelet::InvalId, as an
        # argument; a first template argument is a type, see
        # by_qualified_use)
        return CONSTANT, name
    if CAMEL.match(name) or re.match(r'(?:[&*]\s*)?[A-Za-z_]', after):
        # CamelCase elsewhere (`std::unique_ptr<bond::Bond>`), or a name
        # followed by a name (`ns::archive ar(...)`)
        return TYPE, name
    return OBJECT, name


def _compares(after):
    """Whether the `<` that starts ``after`` compares, opening no template.

    So it does when a `)` or `;` closes its level before any `>`
    (`bp::std_in < pipe)`, boost::process's redirection). A `>` that
    follows (`bp::std_in < p, bp::std_out > out)`) cannot be told from
    template arguments (`f(acme::Grid<T> a, int b)`): they are taken.
    """
    depth = 0
    for char in after[1:]:
        if char in '([{':
            depth += 1
        elif char in ')]}':
            if depth == 0:
                return True
            depth -= 1
        elif char == '>':
            return False
        elif char == ';':
            return True
    return False


# a standard container's template without arguments: itself an argument
# of a template's template parameter
_BARE_STD_TEMPLATE = re.compile(
    r'^(?:::)?std::(?:vector|list|deque|set|map|multiset|multimap|'
    r'unordered_set|unordered_map|basic_string)$')


def template_shape(after, texts):
    """The template_kind of a use, with what the texts declare.

    A lower-case argument the texts declare a variable is a value
    (`Spline<double, 2, spline_dim>`), unless they declare it a type too
    (`using point_t = ...;`, which reads as a declaration of a variable).
    """
    return template_kind(
        after, is_variable=lambda argument: argument not in KEYWORDS and
        argument[:1].islower() and declared_as_variable(argument, texts)
        and argument not in declared_names(texts))


def template_use(name, after, *, unqualified, texts=()):
    """The kind of a name its line follows with template arguments.

    :param texts: the code of the files with errors, where an argument may
      be declared a variable (a value, then)
    """
    end = end_of_template_arguments(after)
    called = end is not None and _CALL.match(after, end)
    # (arguments on the lines after: `convertToTrajectoryPoints<` ends it)
    kind = template_shape(after, texts)
    if (unqualified and not CAMEL.match(name) and called) or \
            (LOWER_CAMEL.match(name) and (called or after.strip() == '<')) \
            or (called and not CAMEL.match(name) and (':' in kind or any(
                _BARE_STD_TEMPLATE.match(a)
                for a in template_arguments(after)))):
        # qobject_cast<QPushButton *>(sender()), also qualified in
        # lowerCamelCase (motion_utils::convertToPath<P>(path)), with a
        # value among its arguments (bg::get<bg::min_corner, 0>(box)) or a
        # template (ranges::to<std::vector>()): a function template;
        # boost::optional<T>(x) is a class
        return FUNCTION
    return kind
