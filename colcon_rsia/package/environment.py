# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The values of colcon-rsia's environment variables, checked up front.

A bad value is one clear error before anything is analysed (a value
silently replaced by the default, or one that fails every package, hides
the mistake): ``colcon rsia analyze`` stops, the build handler says so
once and analyses nothing, the queries check what they read.
"""

import os
import re

from colcon_rsia.environment_variables import \
    CLANG_RESOURCE_DIR_ENVIRONMENT_VARIABLE
from colcon_rsia.environment_variables import \
    CMAKE_WITHOUT_SANDBOX_ENVIRONMENT_VARIABLE
from colcon_rsia.environment_variables import CXX_STD_ENVIRONMENT_VARIABLE
from colcon_rsia.environment_variables import \
    HEADER_MODE_ENVIRONMENT_VARIABLE
from colcon_rsia.environment_variables import OLD_CLANG_RESOURCE_DIR_NAME
from colcon_rsia.safe_files import max_file_mb_problem

# the -std= values of clang for C++ (GNU dialects too)
_CXX_STD = re.compile(
    r'(c|gnu)\+\+(98|03|0x|11|1y|14|1z|17|2a|20|2b|23|2c|26)\Z')
HEADER_MODES = ('model', 'exact')


def _is_resource_dir(value):
    return os.path.isfile(os.path.join(value, 'include', 'stddef.h'))


# (name, whether a value is good, what is expected), for each variable
# whose value is checked: COLCON_RSIA_ALLOWED_ROOTS names directories that
# need not exist on every machine
_CHECKS = [
    (CXX_STD_ENVIRONMENT_VARIABLE.name, lambda v: bool(_CXX_STD.match(v)),
     'a C++ standard such as c++17 or gnu++20'),
    (HEADER_MODE_ENVIRONMENT_VARIABLE.name, lambda v: v in HEADER_MODES,
     ' or '.join(HEADER_MODES)),
    (CLANG_RESOURCE_DIR_ENVIRONMENT_VARIABLE.name, _is_resource_dir,
     'a clang resource directory (with include/stddef.h)'),
    (OLD_CLANG_RESOURCE_DIR_NAME, _is_resource_dir,
     'a clang resource directory (with include/stddef.h)'),
    (CMAKE_WITHOUT_SANDBOX_ENVIRONMENT_VARIABLE.name,
     lambda v: v in ('0', '1'), '1 (or 0)'),
]


def environment_problems():
    """One sentence for each of our variables that holds a bad value."""
    # (imported here: the workers' module loads multiprocessing)
    from colcon_rsia.package.workers import unit_timeout_problem
    from colcon_rsia.package.shared_cache import settings_problems
    problems = []
    size_problem = max_file_mb_problem()
    if size_problem:
        problems.append(size_problem)
    timeout_problem = unit_timeout_problem()
    if timeout_problem:
        problems.append(timeout_problem)
    problems += settings_problems()
    for name, good, expected in _CHECKS:
        value = os.environ.get(name)
        if value and not good(value):
            problems.append(f"{name}='{value}': expected {expected}")
    return problems
