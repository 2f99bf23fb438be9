# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Helpers shared by the benchmarks: building workspaces with colcon."""

import os
from pathlib import Path
import shutil
import subprocess
import sys
import time

REPO = Path(__file__).resolve().parents[1]
CMAKE_ARGS = ['-DCMAKE_EXPORT_COMPILE_COMMANDS=ON',
              '-DPYTHON_EXECUTABLE=/usr/bin/python3']


def colcon():
    candidate = Path(sys.executable).parent / 'colcon'
    return str(candidate) if candidate.exists() else shutil.which('colcon')


def colcon_build(src, root, *, handler=False, extra=()):
    """Clean-build a workspace; return the wall time in seconds."""
    if root.exists():
        shutil.rmtree(root)
    root.mkdir(parents=True)
    args = [colcon(), 'build', '--base-paths', str(src)]
    if handler:
        args += ['--event-handlers', 'rsia+']
    args += list(extra) + ['--cmake-args'] + CMAKE_ARGS
    env = dict(os.environ, COLCON_HOME=str(root / '.colcon_home'))
    started = time.monotonic()
    result = subprocess.run(args, cwd=str(root), env=env,
                            capture_output=True, text=True)
    elapsed = time.monotonic() - started
    if result.returncode != 0:
        raise SystemExit(f'colcon build failed:\n{result.stdout[-3000:]}'
                         f'\n{result.stderr[-3000:]}')
    return elapsed, result.stdout
