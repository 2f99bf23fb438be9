# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The C++ standard headers, precompiled once for every model-mode parse.

The standard headers the model headers include are most of a model-mode
parse: 0.5 s of the 0.6 s an autoware unit takes, and again in each repair
round. They are the same for every unit of a language standard, so they
are compiled once into a precompiled header (``rsia_model/precompiled.h``)
that every parse loads first with ``-include-pch``; the include guards make
the unit's own includes of them no-ops.

One PCH per language standard (clang refuses a PCH made for another), named
by the libclang library file, the resource directory and the header's text
(another libclang cannot read it), in a directory the packages of a
workspace share. A PCH clang cannot load (the system headers changed since
it was built) is deleted, and the units parse without one: the next run
builds it again.
"""

import contextlib
import hashlib
import os
import threading

from colcon_rsia import safe_files
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR

PRECOMPILED_HEADER = os.path.join(
    MODEL_HEADERS_DIR, 'rsia_model', 'precompiled.h')

# the sources a C++ precompiled header can be loaded by (not C, not CUDA)
CXX_EXTENSIONS = ('.cpp', '.cc', '.cxx', '.c++', '.C', '.cp', '.CPP')

_lock = threading.Lock()
# (directory, standard) -> the PCH's path, or None when none can be had
_known = {}

# called with the PCH's path before it is built, and with None after: a
# worker process tells its parent (package/workers.py), so that a crash
# of libclang while it writes the PCH (an abort on a full disk) is said to
# be the PCH's, not the unit's (also the exact mode's: shared_headers.py)
on_build = None


@contextlib.contextmanager
def building(path):
    """While a PCH is built at `path`: :data:`on_build` is told."""
    if on_build is not None:
        on_build(path)
    try:
        yield
    finally:
        if on_build is not None:
            on_build(None)


def precompiled_header(directory, source, arguments, resource_dir):
    """The PCH a unit's parse loads, or None (then it parses without one).

    Built on first use.

    :param str directory: where the workspace's PCHs are kept
    :param str source: the unit's main file
    :param arguments: the unit's libclang arguments (model mode)
    :param str resource_dir: clang's resource directory, as the parse has it
    """
    standard = language_standard(arguments)
    if not source.endswith(CXX_EXTENSIONS) or standard is None:
        return None
    key = (os.path.abspath(directory), standard)
    with _lock:
        if key not in _known:
            _known[key] = _built(key[0], standard, resource_dir)
        return _known[key]


def discard(path):
    """Delete a PCH clang refused to load; its units parse without one."""
    with _lock:
        for key, known in _known.items():
            if known == path:
                _known[key] = None
    try:
        os.unlink(path)
    except OSError:
        pass


def language_standard(arguments):
    """The unit's ``-std`` value ('' when it has none), None for C units."""
    standard = ''
    for i, argument in enumerate(arguments):
        if argument.startswith('-std='):
            standard = argument[len('-std='):]
        elif argument == '-x' and i + 1 < len(arguments) and \
                arguments[i + 1] not in ('c++', 'c++-header'):
            return None
    if standard and '++' not in standard:
        return None  # c11, gnu99: a C unit
    return standard


def _built(directory, standard, resource_dir):
    """The PCH's path, compiled unless there already; None if it fails."""
    import clang.cindex as ci
    with open(PRECOMPILED_HEADER, 'rb') as h:
        text = h.read()
    digest = hashlib.sha1(repr(
        (library_stamp(ci), resource_dir, text)).encode()).hexdigest()[:12]
    path = os.path.join(
        directory, f'std-{standard or "default"}-{digest}.pch')
    if os.path.isfile(path):
        return path
    try:
        # the worker processes of a run (and other runs) that need it
        # wait for the first to build it, then load it
        with safe_files.directory_lock(directory):
            if os.path.isfile(path):
                return path
            with building(path):
                return _compile(path, standard, resource_dir, ci)
    except OSError:
        return None


def _compile(path, standard, resource_dir, ci):
    """Compile the PCH to ``path``; return it, or None if it fails."""
    arguments = ['-x', 'c++-header']
    if standard:
        arguments.append(f'-std={standard}')
    if resource_dir:
        arguments += ['-resource-dir', resource_dir]
    try:
        tu = ci.Index.create().parse(
            PRECOMPILED_HEADER, args=arguments,
            options=ci.TranslationUnit.PARSE_INCOMPLETE)
        if any(d.severity >= ci.Diagnostic.Error for d in tu.diagnostics):
            return None
        # another process building the same PCH, or reading it, never sees
        # half a file
        safe_files.write_file_atomically(path, tu.save)
    except (OSError, ci.TranslationUnitLoadError,
            ci.TranslationUnitSaveError):
        return None
    return path


def library_stamp(ci):
    """The libclang library file: its path, size and time."""
    try:
        library = ci.conf.get_filename()
        stat = os.stat(library)
    except (AttributeError, OSError):
        return None
    return (library, stat.st_size, stat.st_mtime_ns)
