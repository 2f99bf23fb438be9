# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""compile_commands.json -> libclang arguments."""

from dataclasses import dataclass
import glob
import json
import os
import shlex
from typing import List

from colcon_rsia import safe_files
from colcon_rsia.environment_variables import \
    CLANG_RESOURCE_DIR_ENVIRONMENT_VARIABLE
from colcon_rsia.environment_variables import OLD_CLANG_RESOURCE_DIR_NAME

# a compile database may be this many times the size limit of a source: it
# holds a command line per translation unit
COMPILE_DB_SIZE_FACTOR = 8

COMPILE_DB_FILENAME = 'compile_commands.json'

RESOURCE_DIR_HINT = (
    'libclang needs the clang builtin headers (stddef.h); install them with '
    "'apt-get install libclang-common-19-dev' or point "
    f'{CLANG_RESOURCE_DIR_ENVIRONMENT_VARIABLE.name} at a clang resource '
    'directory')

# options that take a separate value that we drop together with it
_DROP_WITH_VALUE = frozenset({'-o', '-MF', '-MT', '-MQ', '-Xclang-cc'})
# options dropped alone (dependency files are not ours to write)
_DROP_ALONE = frozenset({'-c', '-MD', '-MMD', '-M', '-MM', '-MG', '-MP'})


class CompileDatabaseError(RuntimeError):
    """The compile database is missing or unreadable."""


@dataclass
class CompileEntry:
    """One translation unit of the compile database."""

    file: str
    directory: str
    arguments: List[str]   # for libclang: no compiler, no source, no output


def load_compile_database(path):
    """Read a compile database.

    :param str path: The path of ``compile_commands.json``
    :returns: one entry per translation unit (the last one wins)
    :rtype: list
    :raises CompileDatabaseError: if it is missing or malformed
    """
    try:
        # a database lists every unit: larger than a source may be
        raw = json.loads(safe_files.read_bytes(
            path, limit=COMPILE_DB_SIZE_FACTOR * safe_files.max_file_bytes(),
        ).decode('utf-8', errors='surrogateescape'))
    except FileNotFoundError:
        raise CompileDatabaseError(f"no compile database at '{path}'")
    except (OSError, ValueError) as e:
        raise CompileDatabaseError(
            f"unreadable compile database '{path}': {e}")
    if not isinstance(raw, list):
        raise CompileDatabaseError(
            f"malformed compile database '{path}': not a list")
    entries = {}
    for item in raw:
        try:
            directory = item['directory']
            file = os.path.normpath(os.path.join(directory, item['file']))
            if 'arguments' in item:
                argv = list(item['arguments'])
            else:
                argv = shlex.split(item['command'])
        except (KeyError, TypeError, ValueError):
            continue
        entries[file] = CompileEntry(
            file=file, directory=directory,
            arguments=clang_arguments(argv, file, directory))
    return list(entries.values())


def clang_arguments(argv, source, directory):
    """Turn a compiler command line into libclang arguments.

    Drops the compiler, the source, ``-c``, the output and dependency-file
    options, and makes relative include paths absolute.
    """
    args = []
    skip = False
    source_names = {source, os.path.basename(source)}
    for arg in argv[1:]:
        if skip:
            skip = False
            continue
        if arg in _DROP_WITH_VALUE:
            skip = True
            continue
        if arg in _DROP_ALONE or arg.startswith('-o'):
            continue
        if os.path.normpath(os.path.join(directory, arg)) in source_names \
                or arg in source_names:
            continue
        args.append(arg)
    return args


_resource_dir_cache = []


def find_resource_dir():
    """Return the clang resource directory, or None when there is none."""
    if _resource_dir_cache:
        return _resource_dir_cache[0]
    candidates = []
    override = os.environ.get(CLANG_RESOURCE_DIR_ENVIRONMENT_VARIABLE.name) or \
        os.environ.get(OLD_CLANG_RESOURCE_DIR_NAME)
    if override:
        candidates.append(override)
    # the newest installed LLVM first
    found = glob.glob('/usr/lib/llvm-*/lib/clang/*')
    found.sort(key=_version_key, reverse=True)
    candidates.extend(found)
    result = None
    for candidate in candidates:
        if os.path.isfile(os.path.join(candidate, 'include', 'stddef.h')):
            result = candidate
            break
    _resource_dir_cache.append(result)
    return result


def _version_key(path):
    numbers = []
    for part in path.split('/'):
        for piece in part.replace('llvm-', '').split('.'):
            if piece.isdigit():
                numbers.append(int(piece))
    return numbers
