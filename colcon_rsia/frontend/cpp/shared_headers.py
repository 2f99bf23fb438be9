# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The system headers a package's units share, precompiled once (exact mode).

In exact mode a unit's parse is mostly its system headers: a ROS 1 node's
``ros/ros.h`` and messages take 2.0 s of a 2.1 s parse. The units of one
target have the same flags and begin with mostly the same includes, so
those are compiled once into a precompiled header (PCH) that each of them
loads with ``-include-pch``; their include guards make the unit's own
includes of them no-ops, and the unit parses in a few hundredths of a
second. The facts are the same as without it (tests/frontend).

What goes into a PCH keeps every unit's meaning:

- only units with the same arguments and directory share one (clang
  refuses a PCH built with other macros);
- only ``#include <...>`` lines of the block a unit begins with, before any
  other directive or code (a macro defined first could change what a
  header declares); a quoted include there (the unit's own header) is
  passed over, it is resolved next to the unit;
- only headers that every unit sharing the PCH includes there: never one
  a unit does not include, which could clash with the unit's own names
  (the units that include the header most of them include share one, the
  others are grouped again);
- only system headers (``/usr``, ``/opt``): the workspace's headers, whose
  code and macros the analysis reads, each unit parses itself. A PCH that
  reached any other file is not used.

A group shares a PCH only when at least two of its units are parsed; it is
built by the first unit's worker (the others wait for it) and deleted when
the package's analysis ends: the next run parses only what changed.
"""

import collections
import hashlib
import json
import os
import re

from colcon_rsia import safe_files
from colcon_rsia.frontend.cpp.model_mode.precompiled import building
from colcon_rsia.frontend.cpp.model_mode.precompiled import CXX_EXTENSIONS
from colcon_rsia.frontend.cpp.model_mode.precompiled import language_standard
from colcon_rsia.frontend.cpp.model_mode.precompiled import library_stamp

# a header worth sharing is included by this many units to parse
MIN_UNITS = 2

_ANGLE_INCLUDE = re.compile(r'#\s*include\s*<([^<>\n]+)>\s*$')
_QUOTED_INCLUDE = re.compile(r'#\s*include\s*"[^"\n]+"\s*$')
_PRAGMA_ONCE = re.compile(r'#\s*pragma\s+once\s*$')


def leading_includes(text):
    """The ``<...>`` headers of the include block a source begins with.

    Comments, blank lines, ``#pragma once`` and quoted includes are passed
    over; the block ends at any other line.
    """
    text = re.sub(r'/\*.*?\*/', lambda m: '\n' * m.group(0).count('\n'),
                  text, flags=re.DOTALL)
    headers = []
    for line in text.splitlines():
        line = line.split('//', 1)[0].strip()
        if not line or _PRAGMA_ONCE.match(line) or \
                _QUOTED_INCLUDE.match(line):
            continue
        match = _ANGLE_INCLUDE.match(line)
        if match is None:
            break
        headers.append(match.group(1).strip())
    return headers


def plan(entries, *, read_text=safe_files.read_text):
    """{unit file: the text of the header its group shares} of `entries`.

    Units missing from the result parse without a PCH.

    :param entries: the compile entries of the units to parse
    :param read_text: reads a source (safe_files.read_text)
    """
    groups = {}
    for entry in entries:
        if entry.file.endswith(CXX_EXTENSIONS) and \
                language_standard(entry.arguments) is not None:
            key = (tuple(entry.arguments), entry.directory)
            groups.setdefault(key, []).append(entry)
    plans = {}
    for group in groups.values():
        if len(group) < MIN_UNITS:
            continue
        headers = {}
        for entry in group:
            try:
                included = leading_includes(read_text(entry.file))
            except OSError:
                included = []
            headers[entry.file] = [
                h for h in included
                if _is_system_header(h, entry.arguments, entry.directory)]
        for files, shared in _subgroups(headers):
            text = ''.join(f'#include <{h}>\n' for h in shared)
            plans.update(dict.fromkeys(files, text))
    return plans


def _subgroups(headers):
    """[(unit files, the headers all of them include)] to precompile.

    The units that include the header most of them include share what they
    all include (in the order of the first); the others are grouped again
    the same way: a unit that includes none of them does not keep the
    others from sharing theirs.

    :param headers: {unit file: its leading system headers}
    """
    found = []
    left = {f: h for f, h in headers.items() if h}
    while len(left) >= MIN_UNITS:
        counts = collections.Counter(h for hs in left.values() for h in set(hs))
        most, count = max(counts.items(), key=lambda item: (item[1], item[0]))
        if count < MIN_UNITS:
            break
        files = [f for f in left if most in left[f]]
        shared = [h for h in left[files[0]]
                  if all(h in left[f] for f in files)]
        found.append((files, shared))
        for file in files:
            del left[file]
    return found


def _is_system_header(header, arguments, directory):
    """Whether the first include directory that has `header` is a system one.

    A header no include directory has comes from the compiler's own
    directories (the standard library).
    """
    for include_dir in safe_files.include_dirs(arguments, directory):
        if os.path.isfile(os.path.join(include_dir, header)):
            return include_dir.startswith(safe_files.SYSTEM_PREFIXES)
    return True


def precompiled(directory, text, arguments, working_directory,
                resource_dir):
    """(the PCH's path, the files it read) for a group's header, or None.

    Built on first use, by one process of those that need it.

    :param str directory: the package's directory of PCHs
    :param str text: the shared header (:func:`plan`)
    :param arguments: the units' libclang arguments
    """
    import clang.cindex as ci
    digest = hashlib.sha1(repr((
        library_stamp(ci), resource_dir, list(arguments), working_directory,
        text)).encode()).hexdigest()[:16]
    path = os.path.join(directory, f'{digest}.pch')
    try:
        with safe_files.directory_lock(directory):
            if not os.path.isfile(path + '.json'):
                # (a crash meanwhile is the PCH's, not the unit's)
                with building(path):
                    _build(path, text, arguments, working_directory,
                           resource_dir, ci)
            with open(path + '.json', encoding='utf-8') as f:
                inputs = json.load(f)
    except (OSError, ValueError):
        return None
    if inputs is None:
        return None  # it could not be built, or reached the workspace
    return path, inputs


def _build(path, text, arguments, working_directory, resource_dir, ci):
    """Compile the PCH; record the files it read (null: do not use it)."""
    header = path[:-len('.pch')] + '.h'
    with open(header, 'w', encoding='utf-8') as f:
        f.write(text)
    inputs = None
    try:
        # the bodies of the system headers' functions are no fact of the
        # package (clang keeps those a unit's types need: constexpr ones,
        # those whose return type they deduce): a quarter less time
        tu = ci.Index.create().parse(
            header, options=ci.TranslationUnit.PARSE_INCOMPLETE |
            ci.TranslationUnit.PARSE_SKIP_FUNCTION_BODIES,
            args=['-x', 'c++-header'] + _without_language(arguments) + [
                '-resource-dir', resource_dir, '-ferror-limit=0',
                '-working-directory', working_directory])
        names = {i.include.name for i in tu.get_includes()
                 if i.include is not None}
        # named as the unit's own includes are (analysis._unit_facts)
        read = sorted({os.path.abspath(name) for name in names})
        if not any(d.severity >= ci.Diagnostic.Error
                   for d in tu.diagnostics) and all(
                       # (the compiler's own directories are named through
                       # links: /../lib/gcc/…/../../../../include)
                       os.path.realpath(name).startswith(
                           safe_files.SYSTEM_PREFIXES)
                       for name in names):
            safe_files.write_file_atomically(path, tu.save)
            inputs = read
    except (ci.TranslationUnitLoadError, ci.TranslationUnitSaveError):
        pass
    safe_files.write_json_atomically(path + '.json', inputs)


def _without_language(arguments):
    """The arguments without ``-x <language>`` (the PCH is a header)."""
    kept = []
    skip = False
    for argument in arguments:
        if skip:
            skip = False
        elif argument == '-x':
            skip = True
        elif not argument.startswith('-x'):
            kept.append(argument)
    return kept
