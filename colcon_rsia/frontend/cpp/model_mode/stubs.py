# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Writing the stand-ins of one unit into the stub directory.

A stub directory may be shared by the translation units of a package,
parsed in parallel processes: the generated files only ever grow, writes
are atomic and serialised by a lock on the directory (processes share it).
"""

import functools
import os
import re
import threading

from colcon_rsia import safe_files
from colcon_rsia.frontend.cpp.model_mode.c_libraries import c_library_header
from colcon_rsia.frontend.cpp.model_mode.c_libraries import c_library_names
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_LIBRARIES
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_NAMESPACES
from colcon_rsia.frontend.cpp.model_mode.include_scan import read_text
from colcon_rsia.frontend.cpp.model_mode.include_scan import \
    write_atomically
from colcon_rsia.frontend.cpp.model_mode.model_index import declared_names
from colcon_rsia.frontend.cpp.model_mode.model_index import \
    model_declarations
from colcon_rsia.frontend.cpp.model_mode.model_index import \
    model_headers_declaring
from colcon_rsia.frontend.cpp.model_mode.source_names import ALL_CAPS \
    as _ALL_CAPS
from colcon_rsia.frontend.cpp.model_mode.source_names import CAMEL
from colcon_rsia.frontend.cpp.model_mode.source_names import \
    end_of_template_arguments
from colcon_rsia.frontend.cpp.model_mode.source_names import KNOWN_METHODS
from colcon_rsia.frontend.cpp.model_mode.source_names import member_ok
from colcon_rsia.frontend.cpp.model_mode.source_names import template_kind
from colcon_rsia.frontend.cpp.model_mode.source_names import used_names
from colcon_rsia.frontend.cpp.model_mode.source_namespaces import \
    names_in_bodies
from colcon_rsia.frontend.cpp.model_mode.source_namespaces import \
    namespace_openings
from colcon_rsia.frontend.cpp.model_mode.source_namespaces import opens
from colcon_rsia.frontend.cpp.model_mode.source_namespaces import parts
from colcon_rsia.frontend.cpp.model_mode.source_namespaces import \
    using_declarations
from colcon_rsia.frontend.cpp.model_mode.stand_ins import combined_stub_from
from colcon_rsia.frontend.cpp.model_mode.stand_ins import empty_stub
from colcon_rsia.frontend.cpp.model_mode.stand_ins import guessed_namespace
from colcon_rsia.frontend.cpp.model_mode.stand_ins import library_namespace
from colcon_rsia.frontend.cpp.model_mode.stand_ins import merged_ros2_interface
from colcon_rsia.frontend.cpp.model_mode.stand_ins import namespace_key
from colcon_rsia.frontend.cpp.model_mode.stand_ins import nested_in_model
from colcon_rsia.frontend.cpp.model_mode.stand_ins import nested_namespace
from colcon_rsia.frontend.cpp.model_mode.stand_ins import prefix_namespaces
from colcon_rsia.frontend.cpp.model_mode.stand_ins import qt_used
from colcon_rsia.frontend.cpp.model_mode.stand_ins import stand_ins_for
from colcon_rsia.frontend.cpp.model_mode.stand_ins import STUB_MARKER
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import merge_unknown
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import unit_header
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import unit_unknown
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import UNKNOWN_DIR

FIELDS_HEADER = os.path.join('rsia_model', 'fields.h')
IMPLICIT_MESSAGES_HEADER = os.path.join('rsia_model', 'implicit_messages.h')


# directory level each)
MAX_UP_LEVELS = 8


# where each unit's repair header is (recovery/store.py)
REPAIR_DIR = os.path.join('rsia_model', 'repair')
# the catch-all declarations of the model mode: what is declared there
# says nothing of its library but the name the code wrote
CATCH_ALL_DIRS = (UNKNOWN_DIR, REPAIR_DIR)


_lock = threading.Lock()


def write_stand_ins(scanner, codes, stub_dir):
    """Write the stand-ins one TU needs.

    :returns: (the extra include dirs, the namespaces of unknown includes
      that the TU declares itself, the headers the unit includes first:
      model headers declaring what it names but never includes, and the
      stand-ins of namespaces no include names)
    """
    members, constants, field_types, msgs_types, templates, values = \
        used_names(codes)
    named_headers = _model_headers_named(codes, scanner)
    for header in named_headers:
        # (what they include needs its stand-ins too)
        scanner.scan(os.path.join(MODEL_HEADERS_DIR, header))
    stubs = {}   # include name -> content
    for name, kind in sorted(scanner.missing.items()):
        if kind == 'empty':
            stubs[name] = empty_stub(name)
        else:
            stubs.update(stand_ins_for(
                name, codes, name in scanner.included_by_model))
    unknown, own, brought = _unknown_namespaces(stubs, codes, msgs_types)
    implicit = []
    for package, includes in sorted(msgs_types.items()):
        for include in sorted(includes):
            # every message the code names, included or not: the real
            # message headers include their fields' types, so code may
            # name one before its own include of it, or with none at all
            implicit.append(include)
            if include in stubs or scanner.resolve(
                    include, False, stub_dir) is not None:
                continue
            for stub_name, content in stand_ins_for(include, codes).items():
                stubs.setdefault(stub_name, content)
    up_dirs = set()
    # (the units of a package are parsed in several processes)
    with _lock, safe_files.directory_lock(stub_dir):
        # stand-ins before the headers that include them: another TU of the
        # package may be parsing already
        for name, content in stubs.items():
            try:
                target, up = _stub_path(stub_dir, name)
                if target is None:
                    continue
                _write_stub(target, content)
            except OSError:
                continue  # e.g. a name that is also a directory: the
                # include stays unresolved, as with no stand-in at all
            if up:
                up_dirs.add(up)
        added_to = []
        unknown_includes = [
            name for name, stub in stubs.items()
            if stub.startswith(STUB_MARKER + ' kind=empty')]
        # (read only where an unknown include needs it: a costly scan)
        declared = functools.cache(lambda: declared_names(codes))
        qt = qt_used(codes, declared, stubs) if unknown_includes else []
        if qt:
            # (an include it does not have may include Qt)
            added_to.append(unit_header(stub_dir, 'qt', '\n'.join(
                [f'{STUB_MARKER} kind=unknown: what the sources use of Qt',
                 '#pragma once', *qt, ''])))
        c_names = c_library_names(unknown_includes, codes, declared)
        if c_names:
            added_to.append(unit_header(
                stub_dir, 'c_libraries', c_library_header(c_names)))
        for namespace, names in unknown.items():
            if namespace in own:
                added_to.append(unit_unknown(stub_dir, namespace, names))
            else:
                merge_unknown(stub_dir, namespace, names)
        _merge_implicit(stub_dir, implicit)
        _merge_fields(stub_dir, members, constants, field_types, templates,
                      values)
    # (for this unit only, unlike the implicit messages: another unit of
    # the package may include the library's other ROS version's header)
    return sorted(up_dirs), own, [
        os.path.join(MODEL_HEADERS_DIR, header) for header in named_headers
    ] + [os.path.join(stub_dir, UNKNOWN_DIR, namespace_key(namespace) + '.h')
         for namespace in brought] + added_to


def _stub_path(stub_dir, name):
    """Where the stand-in of an include goes: (path, extra include dir)."""
    if os.path.isabs(name):
        return None, None  # never written outside the stub directory
    normalized = os.path.normpath(name)
    parts = normalized.split(os.sep)
    up = 0
    while parts and parts[0] == '..':
        parts.pop(0)
        up += 1
    if not parts or up > MAX_UP_LEVELS or '..' in parts:
        return None, None
    if not up:
        return os.path.join(stub_dir, *parts), None
    # `#include "../x.h"` from an include dir `_up/a` finds `_up/x.h`
    base = os.path.join(stub_dir, '_up')
    up_dir = os.path.join(base, *(['a'] * up))
    os.makedirs(up_dir, exist_ok=True)
    return os.path.join(base, *parts), up_dir


def _write_stub(target, content):
    existing = read_text(target)
    if existing == content:
        return
    if existing is not None and existing.startswith(STUB_MARKER):
        merged = merged_ros2_interface(existing, content)
        if merged is not None:
            # the names one unit spells, and those another one did
            if merged != existing:
                write_atomically(target, merged)
            return
        kinds = {_stub_kind(existing), _stub_kind(content)}
        if kinds <= {'message', 'service', 'service_message'} and \
                len(kinds) > 1:
            # one TU uses the name as a message, another as a service: the
            # combined form serves both (it only ever grows)
            if _stub_kind(existing) == 'service_message':
                return
            content = combined_stub_from(content)
    write_atomically(target, content)


def _stub_kind(text):
    match = re.search(r'kind=(\w+)', text.split('\n', 1)[0])
    return match.group(1) if match else None


def _merge_fields(stub_dir, members, constants, field_types=(),
                  templates=(), values=()):
    """Grow rsia_model/fields.h to hold these member, constant, type names.

    :param templates: members called with template arguments
    :param values: members some use takes for a value (`msg.at = 3`)
    """
    path = os.path.join(stub_dir, FIELDS_HEADER)
    old = read_text(path) or ''
    if not old.startswith(STUB_MARKER):
        old = ''
    old_members = set(re.findall(
        r'RSIA_MODEL_(?:FIELD|METHOD)\((\w+)[,)]', old))
    old_constants = set(re.findall(r'RSIA_MODEL_CONSTANT\((\w+),', old))
    old_types = set(re.findall(r'RSIA_MODEL_FIELD_TYPE\((\w+)\)', old))
    old_templates = set(re.findall(
        r'RSIA_MODEL_FIELD_TEMPLATE\((\w+)\)', old))
    old_values = set(re.findall(r'^// value (\w+)$', old, re.M))
    # an ALL_CAPS constant of one unit, a member of another's code
    # (`filter.UNKNOWN`): a constant (see used_names)
    capitals = {n for n in old_constants | set(constants)
                if _ALL_CAPS.match(n)}
    if old and members <= old_members | old_templates and \
            not capitals & old_members and \
            constants <= old_constants | old_members and \
            set(field_types) <= old_types | old_members and \
            set(templates) <= old_templates | old_values and \
            set(values) <= old_values:
        return
    # a member one unit calls with template arguments (`mat.at<T>(i)`) is a
    # member template for all units, unless one takes it for a value: the
    # template takes plain calls too (`v.at(i)`)
    all_values = sorted(old_values | set(values))
    all_templates = sorted(
        (old_templates | set(templates)) - set(all_values))
    all_members = sorted(
        (old_members | members) - set(all_templates) - capitals)
    taken = set(all_members) | set(all_templates)
    methods = [n for n in all_members
               if n in KNOWN_METHODS and n not in all_values]
    all_members = [n for n in all_members if n not in methods]
    all_constants = sorted((old_constants | constants) - taken)
    all_types = sorted((old_types | set(field_types)) - taken)
    lines = [
        f'{STUB_MARKER} kind=fields',
        '// the member names used after `.` / `->` in the analysed sources,',
        '// the `Type::CONSTANT` names and the `Type::_field_type` names;',
        '// included twice by rsia_model/message.h (no include guard), a name',
        '// that is a macro there is left out']
    for name in all_members:
        lines += [f'#ifndef {name}', f'RSIA_MODEL_FIELD({name})', '#endif']
    for name in all_templates:
        lines += [f'#ifndef {name}', f'RSIA_MODEL_FIELD_TEMPLATE({name})',
                  '#endif']
    for name in methods:
        lines += [f'#ifndef {name}',
                  f'RSIA_MODEL_METHOD({name}, {KNOWN_METHODS[name]})',
                  '#endif']
    for name in all_types:
        lines += [f'#ifndef {name}', f'RSIA_MODEL_FIELD_TYPE({name})',
                  '#endif']
    lines += [f'// value {name}' for name in all_values]
    # distinct values: constants may be `case` labels of one switch
    for i, name in enumerate(all_constants):
        lines += [f'#ifndef {name}', f'RSIA_MODEL_CONSTANT({name}, {i + 1})',
                  '#endif']
    write_atomically(path, '\n'.join(lines) + '\n')


# `top::name` of a model library's namespace, where the code names it
_MODEL_NAME = re.compile(
    r'(?<![\w:.>])(?:::\s*)?('
    + '|'.join(sorted(MODEL_LIBRARIES, key=len, reverse=True))
    + r')\s*::\s*([A-Za-z_]\w*)')


def _model_headers_named(codes, scanner):
    """The model headers declaring what the sources name, never included.

    A real header includes what its declarations use, and code names what
    it brought without including it (`tf2::Vector3` after
    tf2_geometry_msgs). The model's headers include less, so the model
    header declaring a `top::name` of a model library that the unit's
    includes never reach is included first (by this unit alone).

    Not where the workspace has its own copy of the header (the library
    itself: its real headers declare what they declare). Of a library's
    ROS 1 and ROS 2 headers declaring the name, the unit's version's.

    :param scanner: the unit's include scan (what it reached)
    """
    # (a message package's interfaces are the implicit messages)
    named = {match.groups() for code in codes
             for match in _MODEL_NAME.finditer(code)
             if match.group(2) not in ('msg', 'srv', 'action')}
    headers = set()
    for top, name in named:
        found = model_headers_declaring(f'{top}::{name}')
        if found and not any(os.path.join(MODEL_HEADERS_DIR, header)
                             in scanner.visited for header in found):
            headers.add(min(found, key=lambda p: (
                not p.startswith(top + '/'),
                p.endswith('.h') if scanner.ros2 else p.endswith('.hpp'),
                len(p), p)))
    # `boost::bind(&C::f, this, _1)`: the placeholders written bare, which
    # only <boost/bind.hpp>'s using-directive declares (the real headers of
    # ROS 1 and its libraries include it)
    if ('boost', 'bind') in named and \
            any(_BARE_PLACEHOLDER.search(code) for code in codes) and \
            not any(_PLACEHOLDERS_USED.search(code) for code in codes) and \
            os.path.join(MODEL_HEADERS_DIR, _BOOST_BIND) not in scanner.visited:
        headers.add(_BOOST_BIND)
    return sorted(
        header for header in headers
        if scanner.resolve(header, False, '') ==
        os.path.join(MODEL_HEADERS_DIR, header))


_BOOST_BIND = os.path.join('boost', 'bind.hpp')
_BARE_PLACEHOLDER = re.compile(r'(?<![\w:])_[1-9]\b')
_PLACEHOLDERS_USED = re.compile(
    r'\bplaceholders\s*::\s*_[1-9]\s*;|\bnamespace\s+(?:::\s*)?\w+\s*::'
    r'\s*placeholders\b')


def _merge_implicit(stub_dir, implicit):
    """Grow rsia_model/implicit_messages.h by these includes."""
    path = os.path.join(stub_dir, IMPLICIT_MESSAGES_HEADER)
    old = read_text(path) or ''
    old_includes = set(re.findall(r'#include <([^>]+)>', old)) \
        if old.startswith(STUB_MARKER) else set()
    if set(implicit) <= old_includes and old.startswith(STUB_MARKER):
        return
    lines = [
        f'{STUB_MARKER} kind=implicit',
        '// messages the sources name, declared before any use: the real',
        '// message headers include what their fields use']
    lines += [f'#include <{n}>' for n in sorted(old_includes | set(implicit))]
    write_atomically(path, '\n'.join(lines) + '\n')


def _unknown_namespaces(stubs, codes, messages_named):
    """Guess what unknown includes declare.

    :param messages_named: {package: the includes of its messages the
      sources name} (source_names.used_names)
    :returns: ({namespace: (types {name: static members}, objects,
      constants, templates {name: True for a function, (the kind of its
      parameters, static members) for a class}, nested namespaces {name:
      names}, the stand-ins of its messages, the catch-all overloads of
      functions of the sources, aliases {name: the type it stands for})},
      sorted namespaces the TU declares itself
      (their names go to a header of the unit's own), the namespaces no
      include names, which the unit must include)

    For the namespace of each unknown include directory (a package's name is
    its namespace, by ROS convention), the names the sources use after
    `namespace::` are declared: CamelCase names (and names used to declare
    a variable) as catch-all classes, ALL_CAPS names as constants, others as
    catch-all objects (functions, variables). A name used with template
    arguments (`ns::Name<T>`, or `Name<T>` after `using ns::Name;`) is a
    template: a class template when capitalised or used as a type
    (`ns::rtree<V, ns::rstar<16>>`), a function template otherwise. A
    class template's parameters are the shape its uses' arguments fit
    (`Matrix<double, 3, 3>`: a type, then values), and it has the static
    members its uses name (`Matrix<double, 3, 3>::Identity()`); where no
    shape fits every use, the repairs declare it (recovery/). In a
    namespace the sources open themselves (a library's they add to), what
    they write inside their blocks is theirs (_theirs_left); such a
    namespace is named in the second result. What stand-ins of a
    namespace's messages declare (`pcl/PCLHeader.h`), and the messages
    the sources name (msg/, srv/, action/), are theirs in any namespace;
    the namespace's header includes those stand-ins. Below a namespace the model or
    the sources own, the next directory is a nested namespace; a directory
    named after its namespace and more (`dynamixel_sdk/`) gives that
    namespace (stand_ins.nested_namespace, prefix_namespaces).
    """
    empties = [name for name, content in stubs.items()
               if 'kind=empty' in content.split('\n', 1)[0]]
    # namespace -> the stand-ins of its messages (configs, services)
    with_messages = {}
    for name, content in stubs.items():
        if 'kind=empty' not in content.split('\n', 1)[0]:
            with_messages.setdefault(name.split('/')[0], set()).add(name)

    openings = namespace_openings(codes)

    def opened(namespace):
        return any(opens(opening, namespace) for opening in openings)

    def known_top(namespace):
        # a model library's or the sources' own: what an unknown include
        # below it declares is in a namespace nested in it
        return namespace in MODEL_NAMESPACES or (
            namespace not in with_messages and opened(namespace))

    namespaces = {guessed_namespace(name) for name in empties} - {None}
    qualifiers = {m.group(1) for code in codes
                  for m in _QUALIFIER.finditer(code)}
    for name in empties:
        # `top/dir/...`: `top::dir` (any other top namespace is guessed
        # whole, with its nested namespaces)
        nested = nested_namespace(name)
        if nested is not None and known_top(nested.split('::')[0]):
            namespaces.add(nested)
        # `dynamixel_sdk/`: `dynamixel::`, where the sources use it;
        # `corp_planning/` of a stack in `corp::`: `corp::planning`
        for prefix, rest in prefix_namespaces(name):
            if known_top(prefix):
                if nested_in_model(prefix, rest):
                    namespaces.add(f'{prefix}::{rest}')
            elif prefix in qualifiers and library_namespace(prefix):
                namespaces.add(prefix)
    # a namespace no include of the unit names, brought by an unknown
    # header (a library's header includes Eigen's): the unit includes it
    # (a message package's messages have stand-ins, included or implicit)
    brought = sorted(_brought_namespaces(
        qualifiers - namespaces - set(with_messages) - set(messages_named),
        codes)) if empties else []
    namespaces.update(brought)
    # names that are namespaces of their own at the top: `dir::` alone
    # never means `top::dir::` for them
    tops = MODEL_NAMESPACES | {name.split('/')[0] for name in stubs}
    # every `namespace alias = target;` of the sources (read once)
    aliased = {(alias, target) for code in codes
               for alias, target in _NAMESPACE_ALIAS.findall(code)}
    # every `using a::b::name;` of the sources: (('a', 'b'), 'name')
    usings = using_declarations(codes)
    result = {}
    own = []
    for namespace in sorted(namespaces):
        theirs, functions = set(), set()
        messages = with_messages.get(namespace, set())
        if opened(namespace):
            # a library's namespace the sources add to (`namespace pcl {`
            # and their overloads): what they write in it is theirs, the
            # rest of what they use of it the library's
            own.append(namespace)
            theirs, functions = names_in_bodies(
                namespace, codes, openings)
        last = namespace.rsplit('::', 1)[-1]
        spelled = _spelled(namespace, unqualified=last not in tops)
        # (and its aliases: `namespace ec = Eigen;` then `ec::Matrix3f`)
        aliases = sorted({alias for alias, target in aliased
                          if re.fullmatch(spelled, target)})
        use = re.compile(
            r'(?<![\w:])(?:::\s*)?(?:' + '|'.join([spelled] + aliases) +
            r')\s*::\s*([A-Za-z_]\w*)'
            r'(\s*<|\s*::\s*([A-Za-z_]\w*)|\s*[&*]*\s*[A-Za-z_]\w*\s*[;=({,)\[])?')
        types, objects, constants = {}, set(), set()
        nested = {}  # nested namespace -> the names used in it
        class_templates = set()  # (nested namespace, name)
        template_kinds = {}  # name -> the kinds of its uses (template_kind)
        template_members = {}  # name -> its static members the code uses
        scoped = set()  # templates whose use names a type
        for code in codes:
            for match in use.finditer(code):
                name, after, member = match.group(1), match.group(2), \
                    match.group(3)
                if not member_ok(name) or name == last:
                    continue
                if not member and _ELABORATED.search(
                        code, max(0, match.start() - 20), match.start()):
                    # `friend class ns::access;`: a class, whatever its
                    # case
                    types.setdefault(name, set())
                elif after and after.strip() == '<':
                    template_kinds.setdefault(name, set()).add(
                        template_kind(code[match.end(1):].lstrip()))
                    if _class_template_use(code, match.end(1)):
                        scoped.add(name)
                    end = end_of_template_arguments(code, match.end(1))
                    static = end and _STATIC_MEMBER.match(code, end)
                    if static and member_ok(static.group(1)):
                        # `Matrix<double, 3, 3>::Identity()`
                        template_members.setdefault(name, set()).add(
                            static.group(1))
                elif _ALIASED.search(
                        code, max(0, match.start() - 80), match.start()):
                    # `namespace fs = boost::filesystem;`: a namespace
                    nested.setdefault(name, set())
                elif member and re.match(r'^[a-z][a-z0-9_]*$', name):
                    # ns::inner::calc(), ns::inner::Type: a nested
                    # namespace (a class would break `using ns::inner::f;`)
                    names = nested.setdefault(name, set())
                    # (ns::inner::deeper::f: deeper is left to the repairs)
                    if member_ok(member) and not re.match(
                            r'\s*::', code[match.end(3):]):
                        names.add(member)
                    if re.match(r'\s*<(?![<=])', code[match.end(3):]) and (
                            member[:1].isupper() or
                            _class_template_use(code, match.end(3))):
                        # a class template: the repairs declare it with
                        # the parameters of its use
                        class_templates.add((name, member))
                elif member or (CAMEL.match(name) and
                                not _ALL_CAPS.match(name)) or (
                        after and not name.isupper() and
                        not _IN_EXPRESSION.search(
                            code, max(0, match.start() - 40),
                            match.start())):
                    # (ceres::CGNR, an enumerator, is a constant; a class
                    # has lower-case letters)
                    members = types.setdefault(name, set())
                    if member and member_ok(member):
                        members.add(member)
                elif _ALL_CAPS.match(name):
                    constants.add(name)
                else:
                    objects.add(name)
        for name, kinds in _templates_used_unqualified(
                namespace, last not in tops, usings, codes):
            template_kinds.setdefault(name, set()).update(kinds)
        # {name: True (a function) or (the kind of a class template, its
        # static members)}
        templates = {}
        for name, kinds in template_kinds.items():
            if not name[:1].isupper() and name not in scoped:
                # (a catch-all function takes value arguments too)
                templates[name] = True
                continue
            # `Matrix<double, 6, 1>`: a class template with a type and
            # value parameters
            kind = 'template' if kinds == {'template'} else \
                _common_shape(kinds)
            if kind:
                templates[name] = (
                    kind, frozenset(template_members.get(name, ())))
        for name, member in class_templates:
            nested[name].discard(member)
        # a message the sources name is its stand-in's (`pkg::msg::Time`,
        # ROS 1's `pkg::Image`), included or implicit
        for kind in ('msg', 'srv', 'action'):
            if any(include.startswith(f'{namespace}/{kind}/')
                   for include in messages_named.get(namespace, ())):
                nested.pop(kind, None)
        for name in list(types):
            if f'{namespace}/{name}.h' in messages_named.get(namespace, ()):
                del types[name]
        for name in set(template_kinds) | set(nested):
            types.pop(name, None)
        objects -= set(types) | set(template_kinds) | set(nested)
        constants -= set(types) | set(template_kinds) | set(nested)
        overloads = _theirs_left(namespace, codes, openings, (
            theirs, functions), (types, objects, constants, templates, nested))
        aliases = _override_aliases(namespace, types, templates, codes)
        for name in aliases:
            del types[name]
        if types or objects or constants or templates or nested or \
                overloads or aliases:
            result[namespace] = (types, objects, constants, templates,
                                 nested, messages, overloads, aliases)
    # (one the unit adds to has a header of the unit's own)
    return result, own, [name for name in brought
                         if name in result and name not in own]


def _theirs_left(namespace, codes, openings, written, names):
    """Leave to the sources what they write in a namespace they add to.

    What they call there may have the library's overloads too: those are
    declared as catch-all overloads that any of theirs beats.

    :param written: what they write there (names_in_bodies)
    :returns: the overloads, as names relative to the namespace
    """
    theirs, functions = written
    types, objects, constants, templates, nested = names
    overloads = set()
    # (a call without arguments would tie between theirs and a catch-all)
    functions = {name for name in functions
                 if not _called_without_arguments(name, codes)}
    for name in set(types) | objects | constants | set(templates):
        if name in theirs:
            # (a class of theirs has a constructor: only what the uses
            # take for a function is one)
            if name in functions and (name in objects or
                                      templates.get(name) is True):
                overloads.add(name)
            types.pop(name, None)
            templates.pop(name, None)
            objects.discard(name)
            constants.discard(name)
    for name in theirs & set(nested):
        inner_names, inner_functions = names_in_bodies(
            f'{namespace}::{name}', codes, openings)
        if not inner_names:
            # (not a namespace they open: a variable of theirs, say)
            del nested[name]
            continue
        for member in nested[name] & inner_names:
            if member in inner_functions and \
                    not _called_without_arguments(member, codes):
                overloads.add(f'{name}::{member}')
        nested[name] -= inner_names
    return overloads


def _override_aliases(namespace, types, templates, codes):
    """{name: type} of the namespace's names an override returns.

    C++ wants an override to return what the function it overrides
    returns: `ns::Walls walls() override;` beside `virtual
    std::vector<ns::Wall> walls() = 0;` in the sources makes `Walls` the
    library's alias of that type, not a class. Only a type the header of
    the namespace can spell: standard containers of its own names.
    """
    *_, last = namespace.split('::')
    aliases = {}
    sources = '\n'.join(codes)
    for code in codes:
        for match in _OVERRIDER.finditer(code):
            qualifier, name, function = match.groups()
            if name not in types or name in aliases or (
                    qualifier and parts(qualifier)[-1:] != (last,)):
                continue
            base = re.search(r'\bvirtual\s+([^;{}()=]+?)\s*\b' +
                             re.escape(function) + r'\s*\(', sources)
            target = base and re.sub(r'\s+', ' ', base.group(1).strip())
            if target and _spellable(target, namespace, name, types,
                                     templates):
                aliases[name] = target
    return aliases


# `[ns::]Name function(...) [const] [noexcept] [final] override`
_OVERRIDER = re.compile(
    r'(?<![\w:])((?:[A-Za-z_]\w*\s*::\s*)*)([A-Za-z_]\w*)\s+'
    r'([A-Za-z_]\w*)\s*\([^;{}]*?\)\s*(?:const\s*)?(?:noexcept\s*)?'
    r'(?:final\s*)?override\b')
# what a header of an unknown namespace can name besides its own names
# (rsia_model/message.h includes them)
_SPELLABLE = frozenset({
    'std::vector', 'std::array', 'std::string', 'std::size_t', 'bool',
    'char', 'int', 'long', 'short', 'unsigned', 'signed', 'float', 'double',
    'const'})


def _spellable(target, namespace, name, types, templates):
    """Whether the namespace's header can declare an alias of `target`."""
    own = (set(types) | set(templates)) - {name}
    for used in re.findall(r'[A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*',
                           target):
        used = re.sub(r'\s+', '', used)
        if used in _SPELLABLE or used in own or (
                used.startswith(namespace + '::') and
                used[len(namespace) + 2:] in own) or used.isdigit():
            continue
        return False
    return True


def _called_without_arguments(name, codes):
    """Whether the sources call a function `name()`."""
    call = re.compile(r'\b' + name + r'\s*\(\s*\)')
    return any(call.search(code) for code in codes)


def _brought_namespaces(names, codes):
    """Those of `names` (used as `name::`) that may be a library's namespace.

    Not one the model declares, nor one the sources do (a class, an alias,
    a template parameter) or use but as a qualifier (`Name value;`: a
    class). (One search of the sources for all of them: a unit's scanned
    headers may be megabytes.)
    """
    names = {name for name in names if library_namespace(name) and
             name not in model_declarations()}
    if not names:
        return set()
    spelled = '|'.join(sorted(names, key=len, reverse=True))
    alias = re.compile(r'\bnamespace\s+(' + spelled + r')\s*=')
    use = re.compile(r'(?<![\w:.>])(' + spelled + r')\b(?!\s*::)')
    other = set()
    for code in codes:
        other.update(alias.findall(code))
        for match in use.finditer(code):
            # `using namespace name;`, `namespace alias = name;`
            before = code[max(0, match.start() - 80):match.start()]
            if match.group(1) not in other and not (
                    _OPENED.search(before) or _ALIASED.search(before)):
                other.add(match.group(1))
    return names - other


# the namespace an alias names: `namespace fs = boost::filesystem;`
_NAMESPACE_ALIAS = re.compile(
    r'\bnamespace\s+(\w+)\s*=\s*(?:::\s*)?([A-Za-z_][\w\s:]*?)\s*;')


def _common_shape(kinds):
    """The parameters' shape that every use's arguments fit, or None.

    :param kinds: `template:<shape>`s of the uses (source_names.
      template_kind): `rstar<16>` and `rstar<16, 4>` fit `v` and a pack of
      more values; a use of types only (`template`) gives no shape
    """
    shapes = [kind.partition(':')[2] for kind in kinds]
    if not all(shapes):
        return None
    shortest = min(shapes, key=len)
    if all(shape.startswith(shortest) and
           set(shape[len(shortest):]) <= {shortest[-1]} for shape in shapes):
        return f'template:{shortest}'
    return None


# what comes before a name in an expression, where `ns::pi * ratio` is a
# product, not a declaration of a pointer
# `class ` before a qualified name: an elaborated type specifier
_ELABORATED = re.compile(r'\b(?:class|struct|union|enum)\s+\Z')
_IN_EXPRESSION = re.compile(r'(?:[-+*/%=?!|^]|\breturn)\s*\Z')
# what follows the arguments of a class template's use: a member
# (`fieldList<PointT>::type`), a declared name (`shared_ptr<T> cloud`),
# or the end of the template arguments it is one of (`rtree<V, rstar<16>>`:
# a function template's use is a call)
_AFTER_CLASS_TEMPLATE = re.compile(r'\s*(?:::|[&*]*\s*[A-Za-z_]|[>,])')
# a static member after a class template's arguments
_STATIC_MEMBER = re.compile(r'\s*::\s*([A-Za-z_]\w*)\b(?!\s*::)')
# what precedes a type that a use of a template is: `using Tree = `
_ALIAS_OF = re.compile(r'\busing\s+\w+\s*=\s*(?:typename\s+)?[\w:\s]*\Z')


def _class_template_use(code, start):
    """Whether the template's use from ``start`` (its `<`) names a type.

    As `pcl::traits::fieldList<PointT>::type` and `pcl::shared_ptr<T> p`
    do, whatever the case of the template's name.
    """
    end = end_of_template_arguments(code, start)
    return end is not None and (
        _AFTER_CLASS_TEMPLATE.match(code, end) is not None or
        _ALIAS_OF.search(code, max(0, start - 120), start) is not None)


# what precedes the target of a namespace alias
_ALIASED = re.compile(r'\bnamespace\s+\w+\s*=\s*(?:::\s*)?\Z')
# what precedes a namespace's name in `using namespace name;`
_OPENED = re.compile(r'\bnamespace\s*\Z')


def _spelled(namespace, *, unqualified=True):
    """A namespace as the sources may write it: `a::b` also as `b`.

    (Code inside `namespace a` names `b::x` without the `a::`.)
    """
    *parents, last = namespace.split('::')
    if not parents:
        return last
    parents = r'\s*::\s*'.join(parents) + r'\s*::\s*'
    return (f'(?:{parents})?' if unqualified else parents) + last


# a name qualifying another: `dynamixel::PortHandler` (not `a::b` inside)
_QUALIFIER = re.compile(
    r'(?<![\w:.>])(?:::\s*)?([A-Za-z_]\w*)\s*::\s*[A-Za-z_~]')


def _templates_used_unqualified(namespace, unqualified, using_declarations,
                                codes):
    """[(name, {template kinds})] of `using ns::name;` + `name<...>`.

    :param unqualified: whether the sources may write `a::b` as `b`
      (`_spelled`)
    :param using_declarations: the sources' `using` declarations, as
      (qualifier parts, name)
    """
    *parents, last = namespace.split('::')
    spellings = {(*parents, last)} | ({(last,)} if unqualified else set())
    brought = {name for qualifier, name in using_declarations
               if qualifier in spellings}
    found = []
    for name in sorted(brought):
        if not member_ok(name):
            continue
        use = re.compile(r'(?<![\w.:>])' + name + r'\s*<(?![<=])')
        kinds = {template_kind(code[match.end() - 1:])
                 for code in codes for match in use.finditer(code)}
        if kinds:
            found.append((name, kinds))
    return found
