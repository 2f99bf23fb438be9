# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The environment variables colcon-rsia reads.

Registered as ``colcon_core.environment_variable`` entry points, so that
``colcon --help`` lists them. This module is imported on every colcon
call for that: it must stay this small.
"""

from colcon_core.environment_variable import EnvironmentVariable

"""Environment variable choosing the header mode of the analysis"""
HEADER_MODE_ENVIRONMENT_VARIABLE = EnvironmentVariable(
    'COLCON_RSIA_HEADER_MODE',
    'The header mode of the rsia analysis: model (default) or exact')

"""Environment variable with the C++ standard used without a build"""
CXX_STD_ENVIRONMENT_VARIABLE = EnvironmentVariable(
    'COLCON_RSIA_CXX_STD',
    'The C++ standard rsia parses a package without a compile database '
    'with (default: c++17)')

"""Environment variable to override the clang resource directory"""
CLANG_RESOURCE_DIR_ENVIRONMENT_VARIABLE = EnvironmentVariable(
    'COLCON_RSIA_CLANG_RESOURCE_DIR',
    'A clang resource directory (with include/stddef.h) for rsia to use '
    'instead of the newest /usr/lib/llvm-*/lib/clang/*')

"""Environment variable: the largest file read from a package, in MB"""
MAX_FILE_MB_ENVIRONMENT_VARIABLE = EnvironmentVariable(
    'COLCON_RSIA_MAX_FILE_MB',
    'The largest file rsia reads from a package, in megabytes (default: 8)')

"""Environment variable: more directories package files may resolve into"""
ALLOWED_ROOTS_ENVIRONMENT_VARIABLE = EnvironmentVariable(
    'COLCON_RSIA_ALLOWED_ROOTS',
    'Directories (separated by :) outside a package that its files may '
    'link into for rsia to read them')

"""Environment variable: run a package's CMake code without a sandbox"""
CMAKE_WITHOUT_SANDBOX_ENVIRONMENT_VARIABLE = EnvironmentVariable(
    'COLCON_RSIA_CMAKE_WITHOUT_SANDBOX',
    'Set to 1 to let rsia configure an unbuilt package with CMake where no '
    'bubblewrap sandbox can be made (only for code you trust)')

"""Environment variable: the longest one translation unit's parse may take"""
UNIT_TIMEOUT_ENVIRONMENT_VARIABLE = EnvironmentVariable(
    'COLCON_RSIA_UNIT_TIMEOUT',
    'The seconds rsia may spend on one translation unit (its parses and '
    'their walk) before it gives the unit up (default: 900)')

"""Environment variable: a fact cache that runs, clones and machines share"""
CACHE_DIR_ENVIRONMENT_VARIABLE = EnvironmentVariable(
    'COLCON_RSIA_CACHE_DIR',
    'A directory where rsia keeps the facts of translation units by their '
    'content, for every run, checkout and machine that names it')

"""Environment variable: the size of the shared fact cache, in MB"""
CACHE_MB_ENVIRONMENT_VARIABLE = EnvironmentVariable(
    'COLCON_RSIA_CACHE_MB',
    'The size COLCON_RSIA_CACHE_DIR is kept under, in megabytes, by '
    'removing the least recently used facts (default: 1024)')

# the name it had before it followed colcon's COLCON_ prefix; still read
OLD_CLANG_RESOURCE_DIR_NAME = 'RSIA_CLANG_RESOURCE_DIR'
