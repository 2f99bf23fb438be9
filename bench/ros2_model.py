# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Cost of analysing ROS 2 code that was never built (model headers).

Runs ``colcon rsia analyze`` on the ROS 2 test workspace (rclcpp is not
installed: every unit is parsed against the model headers) cold, then again
with nothing changed (the per-unit cache), and the same cold analysis of the
ROS 1 workspace in model mode for comparison. Ends with one line:

RESULT ros2_units=<n> ros2_cold_ms_per_unit=<ms> ros1_cold_ms_per_unit=<ms>
ros2_over_ros1=<ratio> ros2_nochange_s=<s>

Usage: python3 bench/ros2_model.py [--root DIR]
"""

import argparse
import os
from pathlib import Path
import shutil
import subprocess
import time

from common import colcon
from common import REPO


def _analyze(src, root):
    """Wall time of one `colcon rsia analyze` of a workspace, in seconds."""
    env = dict(os.environ, COLCON_HOME=str(root / '.colcon_home'),
               COLCON_RSIA_HEADER_MODE='model')
    started = time.monotonic()
    result = subprocess.run(
        [colcon(), 'rsia', 'analyze', '--base-paths', str(src)],
        cwd=str(root), env=env, capture_output=True, text=True)
    elapsed = time.monotonic() - started
    if result.returncode != 0:
        raise SystemExit(f'analyze failed:\n{result.stderr[-3000:]}')
    return elapsed


def _units(src):
    return sum(1 for _ in src.rglob('*.cpp'))


def _fresh(root):
    if root.exists():
        shutil.rmtree(root)
    root.mkdir(parents=True)
    return root


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--root', default='/tmp/rsia-bench-ros2')
    args = parser.parse_args()
    root = Path(args.root)
    ros2 = REPO / 'test_workspaces' / 'ros2' / 'src'
    ros1 = REPO / 'test_workspaces' / 'ros1' / 'src'
    ros2_root = _fresh(root / 'ros2')
    ros2_cold = _analyze(ros2, ros2_root)
    ros2_warm = _analyze(ros2, ros2_root)
    ros1_cold = _analyze(ros1, _fresh(root / 'ros1'))
    ros2_ms = 1000 * ros2_cold / _units(ros2)
    ros1_ms = 1000 * ros1_cold / _units(ros1)
    print(f'ROS 2: {_units(ros2)} units, {ros2_cold:.1f} s cold, '
          f'{ros2_warm:.1f} s with nothing changed')
    print(f'ROS 1 (model mode): {_units(ros1)} units, {ros1_cold:.1f} s cold')
    print(f'RESULT ros2_units={_units(ros2)} '
          f'ros2_cold_ms_per_unit={ros2_ms:.0f} '
          f'ros1_cold_ms_per_unit={ros1_ms:.0f} '
          f'ros2_over_ros1={ros2_ms / ros1_ms:.2f} '
          f'ros2_nochange_s={ros2_warm:.2f}')


if __name__ == '__main__':
    main()
