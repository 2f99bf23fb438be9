# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The headers declaring what the sources use of unknown namespaces.

rsia_model/unknown/<namespace>.h holds catch-all declarations of the names
the units of a package use after `namespace::` (stubs._unknown_namespaces
guesses them), grown by each unit; a namespace a unit adds to itself gets
a header of that unit's own.
"""

import hashlib
import os
import re

from colcon_rsia.frontend.cpp.model_mode.include_scan import read_text
from colcon_rsia.frontend.cpp.model_mode.include_scan import \
    write_atomically
from colcon_rsia.frontend.cpp.model_mode.model_index import declared_names
from colcon_rsia.frontend.cpp.model_mode.source_names import ALL_CAPS
from colcon_rsia.frontend.cpp.model_mode.source_names import template_head
from colcon_rsia.frontend.cpp.model_mode.stand_ins import namespace_key
from colcon_rsia.frontend.cpp.model_mode.stand_ins import repaired_guard
from colcon_rsia.frontend.cpp.model_mode.stand_ins import STUB_MARKER

UNKNOWN_DIR = os.path.join('rsia_model', 'unknown')


def merge_unknown(stub_dir, namespace, names):
    """Grow rsia_model/unknown/<namespace>.h by these declarations."""
    path = os.path.join(stub_dir, UNKNOWN_DIR, namespace_key(namespace) + '.h')
    old = read_text(path) or ''
    if old.startswith(STUB_MARKER):
        _add_declared(old, names)
    content = _unknown_header(stub_dir, namespace, names)
    if content != old:
        write_atomically(path, content)


def unit_unknown(stub_dir, namespace, names):
    """Write one unit's own declarations of a namespace; return the path.

    (For a namespace the unit adds to: what another unit of the package
    uses of it may be what this one declares.)
    """
    return unit_header(stub_dir, namespace_key(namespace),
                       _unknown_header(stub_dir, namespace, names))


def unit_header(stub_dir, key, content):
    """Write a header of one unit's own, named by its content; its path."""
    digest = hashlib.sha1(content.encode()).hexdigest()[:16]
    path = os.path.join(stub_dir, UNKNOWN_DIR, f'{key}.{digest}.h')
    if read_text(path) != content:
        write_atomically(path, content)
    return path


def _add_declared(old, names):
    """Add what an unknown namespace's header declares to `names`."""
    types, objects, constants, templates, nested, messages, overloads, \
        aliases = names
    messages |= set(re.findall(r'^// stand-in <(.+)>$', old, re.M))
    for match in re.finditer(r'^// alias (\w+) = (.+)$', old, re.M):
        aliases.setdefault(match.group(1), match.group(2))
    overloads |= set(re.findall(r'^// overload (\S+)$', old, re.M))
    for match in re.finditer(r'^// type (\w+):([\w ]*)$', old, re.M):
        types.setdefault(match.group(1), set()).update(
            match.group(2).split())
    objects |= set(re.findall(r'^// object (\w+)$', old, re.M))
    constants |= set(re.findall(r'^// constant (\w+)$', old, re.M))
    for match in re.finditer(
            r'^// (class|function) template (\w+)(?: (template\S*):)?'
            r'([\w ]*)$', old, re.M):
        name = match.group(2)
        if match.group(1) == 'function':
            templates[name] = True
            continue
        kind, members = match.group(3) or 'template', \
            frozenset(match.group(4).split())
        if isinstance(templates.get(name), tuple):
            # (the parameters as another unit declared them)
            members |= templates[name][1]
        templates[name] = (kind, members)
    for match in re.finditer(r'^// namespace (\w+):([\w ]*)$', old, re.M):
        nested.setdefault(match.group(1), set()).update(
            match.group(2).split())


def _unknown_header(stub_dir, namespace, names):
    """The text of a header declaring what the sources use of a namespace."""
    types, objects, constants, templates, nested, messages, overloads, \
        aliases = names
    # (an alias another unit found for a name this one takes for a class)
    for name in aliases:
        types.pop(name, None)
    # what the stand-ins of the namespace's messages declare is theirs:
    # the header includes them instead (a unit may name a message that
    # only an unknown header of the library includes)
    theirs = declared_names(
        '\n'.join(line for line in (read_text(os.path.join(
            stub_dir, message)) or '').split('\n')
            if line[:1] not in (' ', '\t'))
        for message in messages
        if not os.path.isabs(message) and '..' not in message.split('/'))
    for declared in (types, templates, nested):
        for name in theirs & set(declared):
            del declared[name]
    objects -= theirs
    constants -= theirs
    # a name another unit used with template arguments is a template
    for name in set(templates) | set(nested):
        types.pop(name, None)
    objects -= set(types) | set(templates) | set(nested)
    constants -= set(types) | objects | set(templates) | set(nested)
    guard = f'RSIA_MODEL_UNKNOWN_{namespace_key(namespace)}_H'
    lines = [
        f'{STUB_MARKER} kind=unknown: namespace {namespace}',
        f'// what the analysed sources use of `{namespace}::` (from headers the',
        '// model mode does not have): catch-all declarations',
        f'#ifndef {guard}', f'#define {guard}', '',
        '#include <rsia_model/message.h>']
    for message in sorted(messages):
        lines += [f'// stand-in <{message}>', f'#include <{message}>']
    lines.append('')
    for part in namespace.split('::'):
        lines += [f'namespace {part}', '{']
    for name in sorted(types):
        members = sorted(types[name])
        # a repair header (recovery/) may have declared it already
        lines += [f'// type {name}:' + ''.join(' ' + m for m in members),
                  undeclared(f'{namespace}::{name}')]
        lines += catch_all_class(name, members=[
            line for member in members if member not in POINTER_TYPES
            for line in (
                f'#ifndef {member}', f'  static ::rsia_model::Any {member};',
                '#endif')])
        lines.append('#endif')
    for name, declared in sorted(templates.items()):
        if declared is True:
            lines += [f'// function template {name}',
                      undeclared(f'{namespace}::{name}')]
            lines += catch_all_function(name)
        else:
            kind, members = declared
            lines += [f'// class template {name} {kind}:' + ''.join(
                ' ' + m for m in sorted(members)),
                undeclared(f'{namespace}::{name}')]
            lines += catch_all_class(name, head=template_head(kind), members=[
                line for member in sorted(members)
                if member not in POINTER_TYPES for line in (
                    f'#ifndef {member}',
                    f'  static ::rsia_model::Any {member};', '#endif')])
        lines.append('#endif')
    for name, members in sorted(nested.items()):
        lines += [f'// namespace {name}:' + ''.join(
            ' ' + m for m in sorted(members)), f'namespace {name}', '{']
        for member in sorted(members):
            lines.append(undeclared(f'{namespace}::{name}::{member}'))
            if ALL_CAPS.match(member):
                lines.append(f'constexpr int {member} = 1;')
            elif member[:1].isupper():
                lines += catch_all_class(member)
            else:
                lines += catch_all_function(member)
            lines.append('#endif')
        lines.append(f'}}  // namespace {name}')
    # (after the names they may stand for)
    for name, target in sorted(aliases.items()):
        lines += [f'// alias {name} = {target}', undeclared(f'{namespace}::{name}'),
                  f'using {name} = {target};', '#endif']
    # (a repair header, force-included first, may have declared any of
    # them as another kind: a function the sources call, say)
    for name in sorted(objects):
        lines += [f'// object {name}', undeclared(f'{namespace}::{name}'),
                  f'extern ::rsia_model::Any {name};', '#endif']
    for i, name in enumerate(sorted(constants)):
        lines += [f'// constant {name}', undeclared(f'{namespace}::{name}'),
                  f'constexpr int {name} = {i + 1};', '#endif']
    # a function the sources declare (or call) here, which the library
    # overloads: C varargs, the last choice, so that every overload of
    # theirs wins; with explicit template arguments too (`f<T>(x)`)
    for name in sorted(overloads):
        *inner, short = name.split('::')
        lines += [f'// overload {name}', f'#if !defined({short})']
        lines += [f'namespace {part} {{' for part in inner]
        lines += [f'::rsia_model::Any {short}(...);',
                  'template <class... RsiaT>',
                  f'::rsia_model::Any {short}(...);',
                  'template <long long RsiaN, long long... RsiaM>',
                  f'::rsia_model::Any {short}(...);']
        lines += ['}'] * len(inner) + ['#endif']
    lines.append('')
    for part in reversed(namespace.split('::')):
        lines.append(f'}}  // namespace {part}')
    lines += ['', f'#endif  // {guard}', '']
    return '\n'.join(lines)


def undeclared(qualified_name):
    """The opening of a declaration no macro or earlier header made.

    (Its guard tells the later ones: a namespace's own header and its
    parent's, which declares it as nested, may both be in a unit.)
    """
    name = qualified_name.rsplit('::', 1)[-1]
    guard = repaired_guard(qualified_name)
    return f'#if !defined({name}) && !defined({guard})\n#define {guard}'


def catch_all_class(name, *, head='', members=()):
    """The lines of a class of an unknown library, made from anything."""
    # its own assignment from anything (see rsia_model::Unknown), which
    # also hides the base's copy and move assignments: with them, `x = {}`
    # would tie between the class's and the base's. Made from an Unknown
    # too (`Filter<P>::PointCloud`, repaired as one): C++ takes no
    # inherited constructor for that
    # its pointer types by ROS convention, its own (see
    # rsia_model::UnknownPointer); not one of its own name (a class `Ptr`,
    # `cv::Ptr`: C++ forbids a member named as its class)
    pointers = [
        (alias, f'  using {alias} = {target};') for alias, target in (
            ('Ptr', f'::rsia_model::UnknownPointer<{name}>'),
            ('ConstPtr', f'::rsia_model::UnknownPointer<const {name}>'),
            ('SharedPtr', f'::rsia_model::UnknownPointer<{name}>'),
            ('ConstSharedPtr',
             f'::rsia_model::UnknownPointer<const {name}>'))]
    return [f'{head}struct {name} : ::rsia_model::Unknown', '{',
            '  using ::rsia_model::Unknown::Unknown;',
            f'  {name}() = default;',
            f'  {name}(const ::rsia_model::Unknown&);',
            f'  template <class RsiaV> {name}& operator=(RsiaV&&);',
            *[line for alias, line in pointers if alias != name],
            *members, '};']


# the pointer types every class of an unknown library has (see above): no
# member of their names is declared again
POINTER_TYPES = frozenset({'Ptr', 'ConstPtr', 'SharedPtr', 'ConstSharedPtr'})


def catch_all_function(name):
    """The lines of a function of an unknown library, taking anything.

    Explicit template arguments go to RsiaT (`f<T>(x)`), to RsiaN and
    RsiaM (`f<0>(x)`), to both (`get<min_corner, 0>(box)`) or to RsiaC,
    a template (`ranges::to<std::vector>()`); the call's arguments are
    deduced; the braced forms take braced lists, which deduce nothing (see
    rsia_model/message.h).
    """
    return ['template <class... RsiaT, class... RsiaA>',
            f'::rsia_model::Any& {name}(RsiaA&&...);',
            'template <template <class...> class RsiaC, class... RsiaA>',
            f'::rsia_model::Any& {name}(RsiaA&&...);',
            'template <long long RsiaN, long long... RsiaM, class... RsiaA>',
            f'::rsia_model::Any& {name}(RsiaA&&...);',
            'template <class RsiaT, long long RsiaN, long long... RsiaM, '
            'class... RsiaA>',
            f'::rsia_model::Any& {name}(RsiaA&&...);',
            f'RSIA_MODEL_BRACED_FUNCTION({name})']
