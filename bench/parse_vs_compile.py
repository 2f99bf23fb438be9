# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Per translation unit: libclang parse + walk time against g++ -c time.

Builds a test workspace once (default: test_workspaces/ros1), then for
every TU of its compile databases times the real compile command (output to
/dev/null) and the analysis front end (exact mode), in the same run.

Usage: python3 bench/parse_vs_compile.py [--workspace ros1] [--root DIR]
"""

import argparse
import json
import os
from pathlib import Path
import shlex
import subprocess
import time

import clang.cindex as ci
from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.compile_db import find_resource_dir
from colcon_rsia.frontend.compile_db import load_compile_database
from common import colcon_build
from common import REPO


def compile_seconds(entry_command, directory):
    argv = shlex.split(entry_command)
    cleaned = []
    skip = False
    for arg in argv:
        if skip:
            skip = False
            continue
        if arg == '-o':
            skip = True
            continue
        cleaned.append(arg)
    cleaned += ['-o', '/dev/null']
    started = time.monotonic()
    subprocess.run(cleaned, cwd=directory, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - started


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--workspace', default='ros1')
    parser.add_argument('--root', default='/tmp/rsia-bench-parse')
    args = parser.parse_args()
    root = Path(args.root)
    src = REPO / 'test_workspaces' / args.workspace / 'src'
    colcon_build(src, root)
    resource_dir = find_resource_dir()
    rows = []
    for db in sorted((root / 'build').glob('*/compile_commands.json')):
        raw = {os.path.normpath(os.path.join(e['directory'], e['file'])): e
               for e in json.loads(db.read_text())}
        package_path = None
        for entry in load_compile_database(str(db)):
            command = raw[entry.file].get('command') or shlex.join(
                raw[entry.file]['arguments'])
            compile_s = compile_seconds(command, entry.directory)
            started = time.monotonic()
            tu = cpp.parse(ci.Index.create(), file=entry.file,
                           arguments=entry.arguments,
                           resource_dir=resource_dir,
                           working_directory=entry.directory)
            parsed = time.monotonic()
            package_path = package_path or str(
                Path(entry.file).parents[1])
            cpp.extract_facts(tu, package_path=package_path, source='')
            walked = time.monotonic()
            rows.append((os.path.relpath(entry.file, src), compile_s,
                         parsed - started, walked - parsed))
    width = max(len(r[0]) for r in rows)
    print(f"{'translation unit':<{width}}  g++ -c  parse   walk  ratio")
    for name, compile_s, parse_s, walk_s in rows:
        print(f'{name:<{width}}  {compile_s:6.2f}  {parse_s:5.2f}  '
              f'{walk_s:5.2f}  {(parse_s + walk_s) / compile_s:5.2f}')
    total_compile = sum(r[1] for r in rows)
    total_parse = sum(r[2] for r in rows)
    total_walk = sum(r[3] for r in rows)
    print(f'RESULT tus={len(rows)} compile_s={total_compile:.2f} '
          f'parse_s={total_parse:.2f} walk_s={total_walk:.2f} '
          f'analysis_over_compile={(total_parse + total_walk) / total_compile:.2f}')


if __name__ == '__main__':
    main()
