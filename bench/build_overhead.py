# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Wall time of a clean colcon build with and without the rsia handler.

Usage: python3 bench/build_overhead.py [--workspace system] [--root DIR]
"""

import argparse
from pathlib import Path

from common import colcon_build
from common import REPO


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--workspace', default='system')
    parser.add_argument('--root', default='/tmp/rsia-bench-build')
    args = parser.parse_args()
    src = REPO / 'test_workspaces' / args.workspace / 'src'
    root = Path(args.root)
    without, _ = colcon_build(src, root / 'without')
    with_handler, out = colcon_build(src, root / 'with', handler=True)
    lines = [line for line in out.splitlines() if line.startswith('rsia:')]
    print('\n'.join(lines))
    print(f'RESULT build_s={without:.1f} build_rsia_s={with_handler:.1f} '
          f'overhead={(with_handler - without) / without:.2f}')


if __name__ == '__main__':
    main()
