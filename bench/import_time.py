# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What every colcon call pays for colcon-rsia: imports of `--help`.

Every colcon call (``colcon build``, ``--help``, shell completion) loads
the rsia verb and its subverbs. This compares this checkout with another
git revision (default ``HEAD~1``), alternating runs of
``python -X importtime colcon rsia --help`` and ``... rsia impact --help``
in one process, and prints the medians: all imports, colcon_rsia's, and
networkx's.

    python3 bench/import_time.py [REVISION] [--runs N]
"""

import argparse
from pathlib import Path
import re
import statistics
import subprocess
import sys
import tempfile

REPO = Path(__file__).resolve().parents[1]
LINE = re.compile(r'import time:\s+\d+ \|\s+(\d+) \|( *)(\S+)')
COMMANDS = (['rsia', '--help'], ['rsia', 'impact', '--help'])


def _colcon():
    candidate = Path(sys.executable).parent / 'colcon'
    return str(candidate) if candidate.exists() else 'colcon'


def measure(source_dir, words):
    """Microseconds: (all top-level imports, colcon_rsia's, networkx's)."""
    env = {'PYTHONPATH': str(source_dir), 'PATH': '/usr/bin:/bin',
           'HOME': tempfile.gettempdir()}
    result = subprocess.run(
        [sys.executable, '-X', 'importtime', _colcon()] + words,
        capture_output=True, text=True, env=env, check=True)
    total = rsia = networkx = 0
    for line in result.stderr.splitlines():
        match = LINE.match(line)
        if not match:
            continue
        cumulative, depth, name = (
            int(match.group(1)), len(match.group(2)), match.group(3))
        if depth == 1:
            total += cumulative
            if name.startswith('colcon_rsia'):
                rsia += cumulative
        if name == 'networkx':
            networkx = max(networkx, cumulative)
    return total, rsia, networkx


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('revision', nargs='?', default='HEAD~1')
    parser.add_argument('--runs', type=int, default=7)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as old_dir:
        archive = subprocess.run(
            ['git', 'archive', args.revision, 'colcon_rsia'], cwd=REPO,
            capture_output=True, check=True).stdout
        subprocess.run(['tar', '-x', '-C', old_dir], input=archive,
                       check=True)
        for words in COMMANDS:
            samples = {'old': [], 'new': []}
            for _ in range(args.runs):
                samples['old'].append(measure(old_dir, words))
                samples['new'].append(measure(REPO, words))
            medians = {
                side: [statistics.median(s[i] for s in runs) / 1000
                       for i in range(3)]
                for side, runs in samples.items()}
            command = 'colcon ' + ' '.join(words)
            for side, revision in (('old', args.revision), ('new', 'this')):
                total, rsia, networkx = medians[side]
                print(f'{command} ({revision}): imports {total:.0f} ms, '
                      f'colcon_rsia {rsia:.0f} ms, networkx {networkx:.0f} ms')
            print(f'RESULT {command}: imports new/old '
                  f"{medians['new'][0] / medians['old'][0]:.2f}, colcon_rsia "
                  f"new/old {medians['new'][1] / medians['old'][1]:.2f} "
                  f'(median of {args.runs} alternating runs)')


if __name__ == '__main__':
    main()
