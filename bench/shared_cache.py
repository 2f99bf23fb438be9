# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the shared fact cache saves a second clone, measured in one run.

Copies the workspaces of ``test_workspaces/``, as one workspace, to a
first place and analyses it unbuilt (``colcon rsia analyze``) with an empty
``COLCON_RSIA_CACHE_DIR``, then copies it to a second place (another path,
nothing built) and analyses it again with the same cache: what CI does for
a pull request after the main branch's run filled the cache. Prints the
wall times, the units the second run found in the cache, and one line:

RESULT shared_cache_ratio=<second clone time / first run time>
analysis_ratio=<the same, of the time `analyze` reports>

The wall times hold what the cache does not cover: colcon's start, the
model mode preparing each unit's arguments (its key), the Python
packages, writing the summaries.

Usage: python3 bench/shared_cache.py [--root DIR] [--jobs N]
"""

import argparse
import os
from pathlib import Path
import re
import shutil
import subprocess
import sys
import tempfile
import time

from common import colcon
from common import REPO

WORKSPACES = REPO / 'test_workspaces'
ANALYSED = re.compile(r'rsia: analysed \d+ of \d+ packages in ([0-9.]+)s')
SHARED = re.compile(r'rsia: shared cache: (\d+) of (\d+) translation units')


def analyze(root, cache, jobs):
    """(wall seconds, seconds analyze reports, (found, looked up))."""
    env = dict(os.environ, COLCON_HOME=str(root / '.colcon_home'),
               COLCON_RSIA_CACHE_DIR=str(cache))
    args = [colcon(), 'rsia', 'analyze']
    if jobs:
        args += ['--jobs', str(jobs)]
    started = time.monotonic()
    result = subprocess.run(args, cwd=str(root), env=env,
                            capture_output=True, text=True, timeout=3600)
    elapsed = time.monotonic() - started
    analysed = ANALYSED.search(result.stdout)
    shared = SHARED.search(result.stdout)
    if analysed is None or shared is None:
        raise SystemExit(f'colcon rsia analyze failed in {root}:\n'
                         f'{result.stdout[-3000:]}\n{result.stderr[-3000:]}')
    return elapsed, float(analysed.group(1)), (
        int(shared.group(1)), int(shared.group(2)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--root', type=Path, default=None,
                        help='where the clones and the cache are made '
                             '(default: a temporary directory)')
    parser.add_argument('--jobs', type=int, default=None)
    args = parser.parse_args()
    root = args.root or Path(tempfile.mkdtemp(prefix='rsia-shared-cache-'))
    cache = root / 'cache'
    if cache.exists():
        shutil.rmtree(cache)
    first = root / 'first' / 'ws'
    second = root / 'second' / 'a' / 'longer' / 'path' / 'ws'
    for clone in (first, second):
        if clone.exists():
            shutil.rmtree(clone)
        # one workspace of them all (no two packages share a name): one
        # colcon start, as in CI
        for workspace in sorted(WORKSPACES.iterdir()):
            if (workspace / 'src').is_dir():
                shutil.copytree(workspace / 'src',
                                clone / 'src' / workspace.name,
                                symlinks=True)
    wall1, analysis1, _ = analyze(first, cache, args.jobs)
    wall2, analysis2, (found, looked_up) = analyze(second, cache, args.jobs)
    print(f'first run {wall1:.1f} s (analysis {analysis1:.1f} s), second '
          f'clone {wall2:.1f} s (analysis {analysis2:.1f} s), {found} of '
          f'{looked_up} units from the cache', flush=True)
    if not args.root:
        shutil.rmtree(root, ignore_errors=True)
    print(f'RESULT shared_cache_ratio={wall2 / wall1:.2f} '
          f'analysis_ratio={analysis2 / analysis1:.2f}')


if __name__ == '__main__':
    sys.exit(main())
