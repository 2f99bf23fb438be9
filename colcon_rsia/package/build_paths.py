# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The build-only paths under the build base, and the names they take."""

import os

from colcon_rsia.safe_files import display
from colcon_rsia.summary.store import RSIA_DIRNAME

CACHE_DIRNAME = 'cache'


def name_problem(name):
    """Why a package name cannot name a directory under the build base.

    Every path of a package's output is ``<build base>/<name>/…``: a name
    that is not one plain path component (``../../x``, ``a/b``, ``..``)
    would put it elsewhere. None when the name is fine.
    """
    if not name or name in ('.', '..') or '\0' in name or \
            any(s and s in name for s in (os.sep, os.altsep)):
        return (f"the package name '{display(name)}' is not a plain "
                'directory name: its results would be written outside the '
                'build base; skipped')
    return None


def cache_dir(package_build_base):
    """Return the per-TU cache directory of a package's build directory."""
    return os.path.join(package_build_base, RSIA_DIRNAME, CACHE_DIRNAME)


def precompiled_dir(package_build_base):
    """Where the model mode's precompiled headers are kept.

    Beside the packages' build directories, shared by them all (they are
    the same for every package); no package is named with a leading dot.
    """
    return os.path.join(
        os.path.dirname(os.path.abspath(package_build_base)),
        '.' + RSIA_DIRNAME, 'precompiled')


def shared_headers_dir(package_build_base):
    """Where the exact mode's precompiled headers of a package are built.

    Its own (they are made with the package's flags), deleted when its
    analysis ends.
    """
    return os.path.join(package_build_base, RSIA_DIRNAME, 'shared-headers')


def workspace_repairs_file(package_build_base):
    """Where the model mode's repairs every package may need are kept.

    Beside the precompiled headers: one file for the workspace.
    """
    return os.path.join(
        os.path.dirname(precompiled_dir(package_build_base)), 'repairs',
        'workspace.json')
