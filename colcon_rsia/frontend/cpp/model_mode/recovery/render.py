# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The repair header: declarations rendered from a unit's repairs.

Permissive declarations: classes derive from ``rsia_model::Unknown``
(constructible from anything, with every member name the sources use),
objects and functions are of or return ``rsia_model::Any``. Each is
guarded, so that a stand-in or a later header steps aside.
"""

from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import ALL_CAPS
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import base_kind
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import CONSTANT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import FUNCTION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import INCLUDES
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import is_edit
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import K_CONSTANT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import LITERAL
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import \
    MACRO_CONDITION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MACRO_EMPTY
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import \
    MACRO_FUNCTION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MACRO_VALUE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MACRO_VOID
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_KINDS
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_SCOPE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import \
    MEMBER_TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_TYPE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MODEL_MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NAMESPACE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NO_HASH
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NO_OVERRIDE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import SPECIALIZED
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TYPE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import VALUE
from colcon_rsia.frontend.cpp.model_mode.source_names import template_head
from colcon_rsia.frontend.cpp.model_mode.stand_ins import repaired_guard
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import catch_all_class
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import \
    catch_all_function
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import POINTER_TYPES

MARKER = '// colcon-rsia repairs v1'


def render(repairs, source):
    """The repair header holding these declarations."""
    return '\n'.join(_render(repairs, source)[0])


def repairs_at(repairs, source, line_numbers):
    """The repairs whose declarations are on these lines of their header.

    The header is rendered again from the data: a line clang reports an
    error on belongs to one repair's block (a member's, to its class's).
    """
    _, owners = _render(repairs, source)
    return {owners[number - 1] for number in line_numbers
            if 0 < number <= len(owners) and owners[number - 1]}


def _render(repairs, source):
    """The header's lines, and the repair each line belongs to (or None)."""
    lines = [
        f'{MARKER} for {_printable(source)}',
        "// declarations clang said were missing (colcon_rsia's recovery/)",
        '#pragma once', '#include <rsia_model/message.h>', '']
    constant_values = {}
    members = {}
    for kind, name in repairs:
        if kind in MEMBER_KINDS:
            owner, member = name.rsplit('::', 1)
            members.setdefault(owner, set()).add((kind, member))
    owners = []
    owner = None
    for kind, name in sorted(repairs):
        owners += [owner] * (len(lines) - len(owners))
        owner = (kind, name)
        lines.append(f'// repair {kind} {name}')
        *namespaces, short = name.split('::')
        trailer = ''  # after the declaration, outside its namespaces
        if kind in MEMBER_KINDS:
            continue  # in its type's declaration
        if is_edit(kind) or kind.startswith(MODEL_MEMBER):
            # made to the code in memory (edits.py), added to a model
            # class for the parse (overlay.py)
            continue
        if kind in INCLUDES:
            lines.append(f'#include <{name}>')
            continue
        if kind == NO_OVERRIDE:
            lines += ['#define override', '#define final']
            continue
        if kind == NO_HASH:
            continue  # (see TYPE below)
        if kind == LITERAL:
            # (a string's, an integer's and a floating literal's forms)
            lines += [f'::rsia_model::Any& operator""{short}({parameters});'
                      for parameters in ('const char*, unsigned long',
                                         'unsigned long long', 'long double')]
            continue
        if kind == MACRO_FUNCTION:
            # the head of a function of its own name, whose parameters are
            # the arguments after the first (`m` of PYBIND11_MODULE(name,
            # m), used in the body); __LINE__ tells two uses apart
            lines += [
                '#ifndef RSIA_MACRO_BODY', '#define RSIA_MACRO_BODY_(line) '
                'rsia_macro_body_##line',
                '#define RSIA_MACRO_BODY(line) RSIA_MACRO_BODY_(line)',
                '#endif', f'#ifndef {short}',
                f'#define {short}(first, ...) static void '
                'RSIA_MACRO_BODY(__LINE__)(::rsia_model::Any __VA_ARGS__)',
                '#endif']
            continue
        if kind.startswith('macro-'):
            definition = {
                MACRO_VALUE: f'{short}(...) (::rsia_model::any_value())',
                MACRO_VOID: f'{short}(...)', MACRO_EMPTY: short,
                MACRO_CONDITION: f'{short}(...) 1'}[kind]
            lines += [f'#ifndef {short}', f'#define {definition}', '#endif']
            continue
        if kind == NAMESPACE:
            namespaces, body = namespaces + [short], ''
        elif kind == TYPE and short.endswith('s') and \
                (TYPE, name[:-1]) in repairs and name not in members:
            # VirtualWalls beside VirtualWall, ConstLanelets beside
            # ConstLanelet: by the convention of ROS code (autoware,
            # lanelet2) a vector of them; as a class of its own, it would
            # differ from the `std::vector<VirtualWall>` other code writes
            body = f'using {short} = std::vector<{short[:-1]}>;'
        elif base_kind(kind) in (TYPE, TEMPLATE):
            if kind == TYPE and (NO_HASH, name) not in repairs:
                # a key of std::unordered_map (boost::uuids::uuid)
                trailer = f' template <> struct std::hash<::{name}> : ' \
                    '::rsia_model::UnknownHash {};'
            body = _one_line(catch_all_class(
                short, head=template_head(kind) if kind != TYPE else '',
                members=[{
                    MEMBER: _member_value(
                        m, lambda: constant_values.setdefault(
                            f'{name}::{m}', len(constant_values) + 1)),
                    MEMBER_TYPE: f'using {m} = ::rsia_model::Unknown;',
                    MEMBER_SCOPE: f'using {m} = {short};',
                    MEMBER_TEMPLATE:
                        f'RSIA_MODEL_MEMBER_TEMPLATE(static, {m}, )',
                }[k] for k, m in sorted(members.get(name, ()))
                    if m not in POINTER_TYPES]))
        elif kind == FUNCTION:
            body = _one_line(catch_all_function(short))
        elif kind == SPECIALIZED:
            # beside the calls' catch-all, a template an explicit
            # specialisation matches: its return type and parameters are
            # deduced from the specialisation's (a call deduces no RsiaR,
            # and explicit template arguments all go to RsiaT)
            body = _one_line(catch_all_function(short) + [
                'template <class... RsiaT, class RsiaR, class... RsiaA>',
                f'RsiaR {short}(RsiaA...);'])
        elif kind in (CONSTANT, VALUE):
            value = constant_values.setdefault(name, len(constant_values) + 1)
            body = f'constexpr int {short} = {value};'
        else:
            body = f'extern ::rsia_model::Any {short};'
        opening = ' '.join(f'namespace {n} {{' for n in namespaces)
        closing = '}' * len(namespaces)
        # (a namespace's guard repeats its last name: it declares nothing
        # a stand-in could step aside for)
        guard = repaired_guard('::'.join(namespaces + [short]))
        lines += [f'#ifndef {short}', f'#define {guard}',
                  f'{opening} {body} {closing}{trailer}'.strip(), '#endif']
    owners += [owner] * (len(lines) - len(owners))
    lines.append('')
    return lines, owners + [None]


def _member_value(member, value):
    """The declaration of a static member of a class a repair declared.

    A constant by its name (`kLEGACY_CALIBRATION`, `MAX_SIZE`: an
    enumerator of the real class, a `case` label) is a distinct int;
    any other a catch-all.
    """
    if K_CONSTANT.match(member) or (ALL_CAPS.match(member) and
                                    len(member) > 1):
        return f'static constexpr int {member} = {value()};'
    return f'static ::rsia_model::Any {member};'


def _one_line(lines):
    """A declaration of stubs.py's on the one line of its repair."""
    return ' '.join(line.strip() for line in lines)


def _printable(text):
    return text.encode('ascii', 'replace').decode('ascii')
