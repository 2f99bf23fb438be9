# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Executables of unbuilt packages: our CMake configure vs the text reader.

For every CMake package of a workspace (a directory with ``package.xml``
and ``CMakeLists.txt``; the sources are only read), configures it the way
an unbuilt analysis does (:mod:`colcon_rsia.package.cmake_configure`, into
a temporary build base) and reads its ``CMakeLists.txt`` with the fallback
reader, then prints:

- the packages CMake configured and those it failed on (first error);
- the wall seconds per configure (median, mean, max);
- the executables each finds, and every difference of names or sources.

Ends with one line:

RESULT ws=<name> packages=<n> configured=<n> (<pct>%) fell_back=<n>
configure_s_median=<s> configure_s_mean=<s> configure_s_max=<s>
executables_configure=<n> executables_reader=<n> only_configure=<n>
only_reader=<n> other_sources=<n>

Usage: python3 bench/cmake_discovery.py WS [--quiet]
"""

import argparse
import os
import statistics
import sys
import tempfile
import time

from colcon_rsia.package import cmake_configure
from colcon_rsia.package import nodes


def cmake_packages(workspace):
    """Package directories with a CMakeLists.txt, sorted."""
    found = []
    for root, dirs, names in os.walk(workspace):
        if 'COLCON_IGNORE' in names:
            dirs[:] = []
            continue
        dirs[:] = sorted(d for d in dirs if not d.startswith('.'))
        if 'package.xml' in names:
            dirs[:] = []  # a package holds no other package
            if 'CMakeLists.txt' in names:
                found.append(root)
    return found


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('workspace')
    parser.add_argument('--quiet', action='store_true',
                        help='print the differences and totals only')
    args = parser.parse_args(argv)
    workspace = os.path.abspath(args.workspace)
    packages = cmake_packages(workspace)
    if not packages:
        sys.exit(f'no CMake package under {workspace}')
    cmake, version = cmake_configure.cmake_version()
    print(f'{len(packages)} CMake packages; cmake {cmake} {version}')
    seconds, failures = [], []
    totals = dict(configure=0, reader=0, only_configure=0, only_reader=0,
                  other_sources=0)
    with tempfile.TemporaryDirectory(prefix='rsia_cmake_') as scratch:
        for path in packages:
            name = os.path.relpath(path, workspace)
            started = time.monotonic()
            configured = cmake_configure.configure_package(
                path, os.path.join(scratch, name.replace(os.sep, '_')))
            seconds.append(time.monotonic() - started)
            read = nodes._executables_from_cmakelists(path)
            totals['reader'] += len(read)
            if configured.executables is None:
                failures.append((name, configured.problem))
                print(f'FELL BACK {name}: {configured.problem}')
                continue
            found = configured.executables
            totals['configure'] += len(found)
            if not args.quiet:
                print(f'{name}: {len(found)} executables '
                      f'({len(read)} read) in {seconds[-1]:.2f}s')
            for executable in sorted(set(found) | set(read)):
                if executable not in read:
                    totals['only_configure'] += 1
                    print(f'  only configure: {name} {executable} '
                          f'{_relative(found[executable], path)}')
                elif executable not in found:
                    totals['only_reader'] += 1
                    print(f'  only reader:    {name} {executable} '
                          f'{_relative(read[executable], path)}')
                elif sorted(found[executable]) != sorted(read[executable]):
                    totals['other_sources'] += 1
                    print(f'  other sources:  {name} {executable} '
                          f'configure {_relative(found[executable], path)} '
                          f'reader {_relative(read[executable], path)}')
    configured_count = len(packages) - len(failures)
    print(f'RESULT ws={os.path.basename(os.path.dirname(workspace)) or workspace}'
          f' packages={len(packages)} configured={configured_count} '
          f'({100 * configured_count / len(packages):.0f}%) '
          f'fell_back={len(failures)} '
          f'configure_s_median={statistics.median(seconds):.2f} '
          f'configure_s_mean={statistics.mean(seconds):.2f} '
          f'configure_s_max={max(seconds):.2f} '
          f"executables_configure={totals['configure']} "
          f"executables_reader={totals['reader']} "
          f"only_configure={totals['only_configure']} "
          f"only_reader={totals['only_reader']} "
          f"other_sources={totals['other_sources']}")


def _relative(paths, package):
    return ' '.join(os.path.relpath(p, package) for p in paths)


if __name__ == '__main__':
    main()
