# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The compile arguments a unit keeps in the model mode.

``-D``, ``-U``, ``-std`` and the include directories inside a source tree
of the workspace (never a build tree): the rest names the real headers.
"""

import os

# (message headers of devel/ or build/ pull in real ROS headers)
BUILD_DIR_NAMES = frozenset({
    'build', 'devel', 'install', 'log', 'build_isolated', 'devel_isolated',
    'install_isolated'})
# a directory holding one of these is no source tree
BUILD_MARKERS = ('COLCON_IGNORE', 'CATKIN_IGNORE', 'AMENT_IGNORE',
                 'CMakeCache.txt')


_INCLUDE_OPTIONS = ('-I', '-isystem', '-iquote', '-idirafter')


def filter_arguments(arguments, roots, directory):
    """Return (kept arguments, [(kind, dir)] of the kept include dirs)."""
    kept = []
    search = []
    base = directory or os.getcwd()
    i = 0
    while i < len(arguments):
        arg = arguments[i]
        option, value, used = _split_option(arguments, i)
        i += used
        if option in ('-D', '-U'):
            kept += [option + value] if value else []
        elif option == '-std':
            kept.append(arg)
        elif option in _INCLUDE_OPTIONS and value:
            path = os.path.normpath(os.path.join(base, value))
            if _in_source_tree(path, roots):
                kept += [option, path]
                search.append((option, path))
    return kept, search


def _split_option(arguments, i):
    """Return (option, value, number of arguments used) at position i."""
    arg = arguments[i]
    if arg.startswith('-std='):
        return '-std', arg[5:], 1
    for option in ('-isystem', '-iquote', '-idirafter', '-I', '-D', '-U'):
        if arg == option:
            value = arguments[i + 1] if i + 1 < len(arguments) else ''
            return option, value, 2
        if arg.startswith(option):
            return option, arg[len(option):], 1
    return None, None, 1


def real_path(path):
    """The absolute path with its links resolved."""
    return os.path.realpath(os.path.abspath(path))


def is_inside(path, root):
    """Whether `path` is `root` or lies below it."""
    return path == root or path.startswith(root.rstrip('/') + '/')


def _in_source_tree(path, roots):
    """Whether a directory lies in a source tree (never a build tree)."""
    real = real_path(path)
    for root in roots:
        if not is_inside(real, root):
            continue
        relative = os.path.relpath(real, root)
        parts = [] if relative == '.' else relative.split(os.sep)
        current = root
        for part in parts:
            if part in BUILD_DIR_NAMES:
                return False
            current = os.path.join(current, part)
            if any(os.path.exists(os.path.join(current, marker))
                   for marker in BUILD_MARKERS):
                return False
        return True
    return False
