# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Time the Python front end per file, and whole-package analyses.

    python3 bench/python_frontend.py [PACKAGE_DIR ...]

Default: the packages of test_workspaces/python/src. "cold" parses every
module again (empty parse cache); "warm" reuses the parsed modules of the
previous run, as a second package analysis in the same process does.
"""

import os
from pathlib import Path
import statistics
import sys
import time

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from colcon_rsia.frontend import python as front  # noqa: E402,I100
from colcon_rsia.frontend.python import scopes as front_scopes  # noqa: E402,I100
from colcon_rsia.package.python_analysis import build_python_summary  # noqa: E402
from colcon_rsia.package.python_nodes import find_python_nodes  # noqa: E402

ROUNDS = 20


def _per_file(package):
    layout = find_python_nodes(str(package))
    cold = []
    warm = []
    for name, path in sorted(layout.modules.items()):
        for times, clear in ((cold, True), (warm, False)):
            samples = []
            for _ in range(ROUNDS):
                if clear:
                    front_scopes.MODULE_CACHE.clear()
                started = time.perf_counter()
                front.extract_python_facts(
                    path, package_path=str(package), module_name=name,
                    package_modules=layout.modules)
                samples.append(time.perf_counter() - started)
            times.append((statistics.median(samples), os.path.getsize(path),
                          os.path.relpath(path, package)))
    return cold, warm


def main(argv):
    packages = [Path(p).resolve() for p in argv] or sorted(
        p.parent for p in (REPO / 'test_workspaces' / 'python' / 'src').glob(
            '*/package.xml'))
    all_cold, all_warm = [], []
    for package in packages:
        cold, warm = _per_file(package)
        all_cold += [c[0] for c in cold]
        all_warm += [w[0] for w in warm]
        front_scopes.MODULE_CACHE.clear()
        started = time.perf_counter()
        summary = build_python_summary(name=package.name, path=str(package))
        whole = time.perf_counter() - started
        print(f'{package.name}: {len(cold)} files, '
              f'{len(summary.nodes)} nodes, package analysis {whole * 1e3:.1f} '
              f'ms (cold)')
        for (seconds, size, name), (warm_seconds, _, _) in zip(cold, warm):
            print(f'  {name:45} {size:6d} B  cold {seconds * 1e3:6.2f} ms  '
                  f'warm {warm_seconds * 1e3:6.2f} ms')
        print(f'  median per file: cold '
              f'{statistics.median(c[0] for c in cold) * 1e3:.2f} ms, warm '
              f'{statistics.median(w[0] for w in warm) * 1e3:.2f} ms')
    cold_ms = statistics.median(all_cold) * 1e3
    warm_ms = statistics.median(all_warm) * 1e3
    print(f'RESULT files={len(all_cold)} cold_ms_per_file={cold_ms:.2f} '
          f'warm_ms_per_file={warm_ms:.2f} warm_over_cold={warm_ms / cold_ms:.2f}')


if __name__ == '__main__':
    main(sys.argv[1:])
