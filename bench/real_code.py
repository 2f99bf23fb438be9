# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""How much of a real workspace the analysis understands, unbuilt.

Runs ``colcon rsia analyze`` from the root of any workspace (its packages
never built: the default model header mode), the way a user runs it, then
compares what the summaries record with what the source text shows:

- call-site recall: of the calls that create a publisher or subscription in
  the packages' own code (tests aside; found by
  :mod:`colcon_rsia.package.call_sites`), the share that ended up as a fact of a
  node in the summaries (same file, same line, or within two lines for a
  call spread over several);
- translation units, and those with parse errors located in package code;
- packages that failed (internal errors are bugs);
- wall seconds per translation unit and the peak memory of the analysis;
- where the time went: the summaries' ``phases`` summed over the packages.

Ends with one line:

RESULT ws=<name> packages=<n> failed=<n> internal_errors=<n> units=<n>
units_with_errors=<n> (<pct>%) units_losing_calls=<n> (<pct>%)
pub_recall=<pct> (<hit>/<sites>)
sub_recall=<pct> (<hit>/<sites>) pub_in_nodes=<pct> sub_in_nodes=<pct>
from_tokens=<n> rejected_summaries=<n> parses_per_unit=<n> s_per_unit=<s>
peak_mb=<mb>

``units_losing_calls`` counts the units with errors whose parse lost a
publisher, subscription, publish or timer call the text shows (errors
that cost no fact are left unrepaired when repairing does not pay);
``from_tokens`` counts the recorded call sites whose fact was read from
tokens (the parse had lost the call); ``rejected_summaries`` the summaries
the query side would not read (it must be 0); ``parses_per_unit`` the
libclang parses per unit, its repairs included.

The recall counts a call site with a fact anywhere in the package's units;
``*_in_nodes`` only those a node of the summary runs (a plugin's are in no
node until plugins are analysed as nodes).

``--reuse`` scores the summaries already in the build base (those a
``bench/labels.py`` run wrote, say) without analysing again: the seconds
and the memory are then not measured (``s_per_unit`` is the packages'
own analysis time, ``peak_mb`` is ``n/a``).

Usage: python3 bench/real_code.py WS [--colcon EXE] [--jobs N]
  [--build-base DIR] [--base-paths P ...] [--repair POLICY] [--missed]
  [--reuse]
"""

import argparse
import collections
import json
import os
from pathlib import Path
import re
import resource
import shutil
import subprocess
import sys
import time

from common import colcon
from common import REPO

sys.path.insert(0, str(REPO))
from colcon_rsia.package.call_sites import PUBLISHER  # noqa: E402,I100,I202
from colcon_rsia.package.call_sites import scan_package  # noqa: E402
from colcon_rsia.package.call_sites import SUBSCRIBER  # noqa: E402
from colcon_rsia.package.coverage import match_sites  # noqa: E402
from colcon_rsia.summary.store import read_summary  # noqa: E402
from colcon_rsia.summary.store import SummaryError  # noqa: E402

CXX_SOURCES = ('.cpp', '.cc', '.cxx', '.c++', '.C')


def _analyze(ws, build_base, colcon_exe, jobs, base_paths, repair=None):
    args = [colcon_exe, 'rsia', 'analyze', '--build-base', str(build_base)]
    if repair:
        args += ['--repair', repair]
    if base_paths:
        args += ['--base-paths'] + base_paths
    if jobs:
        args += ['--jobs', str(jobs)]
    env = dict(os.environ, COLCON_HOME=str(build_base / '.colcon_home'))
    started = time.monotonic()
    result = subprocess.run(args, cwd=str(ws), env=env,
                            capture_output=True, text=True)
    elapsed = time.monotonic() - started
    peak_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    if result.returncode != 0:
        raise SystemExit(f'analyze failed ({result.returncode}):\n'
                         f'{result.stdout[-3000:]}\n{result.stderr[-3000:]}')
    return elapsed, peak_kb / 1024, result.stdout


def _packages(ws, names):
    """[(name, absolute path)] of the packages the analysis went through.

    The paths are those of the ``package.xml`` naming them (every package
    of a ROS workspace has one).
    """
    paths = {}
    for root, dirs, files in os.walk(ws):
        dirs[:] = [d for d in dirs if not d.startswith(('.', 'build'))
                   and d not in ('install', 'log')]
        if 'package.xml' in files:
            with open(os.path.join(root, 'package.xml'), 'rb') as h:
                match = re.search(rb'<name>\s*([^<\s]+)\s*</name>', h.read())
            if match:
                paths.setdefault(match.group(1).decode(), root)
    return [(name, paths[name]) for name in names if name in paths]


def _summary(build_base, package):
    try:
        with open(build_base / package / 'rsia' / 'summary.json',
                  encoding='utf-8') as h:
            return json.load(h)
    except (OSError, ValueError):
        return None


def _recorded(summary, sites):
    """(sites counted, {sites with a fact}, {sites with a fact of a node}).

    From the summary's coverage section; a summary of an older analyser
    has none: its nodes' endpoints are matched here (node facts only).
    """
    coverage = summary.get('coverage') if summary else None
    if coverage is None:
        lines = _node_lines(summary) if summary else {}
        hits = match_sites(sites, lines)
        return sites, hits, hits
    recorded = {(c['file'], c['line'], c['role']): c['recorded']
                for c in coverage.get('call_sites', [])}
    # a header no unit includes is code the build never compiles
    sites = [s for s in sites
             if recorded.get((s.file, s.line, s.role)) != 'unread']
    facts = {s for s in sites
             if recorded.get((s.file, s.line, s.role), 'none') != 'none'}
    in_nodes = {s for s in sites
                if recorded.get((s.file, s.line, s.role)) == 'node'}
    return sites, facts, in_nodes


def _node_lines(summary):
    """{(file, role): [lines]} of the endpoints of the summary's nodes."""
    lines = collections.defaultdict(list)
    for node in summary.get('nodes', []):
        for role, key in ((PUBLISHER, 'publishers'),
                          (SUBSCRIBER, 'subscribers')):
            for fact in node.get(key, []):
                file, _, line = fact['location'].rpartition(':')
                if line.isdigit():
                    lines[(file, role)].append(int(line))
    return lines


def _parses(summary):
    """(parses, units with coverage): each unit's first and repairs."""
    units = ((summary or {}).get('coverage') or {}).get('units', [])
    return sum(1 + u.get('repair_rounds', 0) for u in units), len(units)


def _from_tokens(summary):
    """The call sites recorded from tokens where the parse lost them."""
    sites = ((summary or {}).get('coverage') or {}).get('call_sites', [])
    return sum(1 for c in sites if c.get('origin') == 'tokens')


def _accepted(build_base, package):
    """Whether the query side accepts the summary the analysis wrote."""
    path = build_base / package / 'rsia' / 'summary.json'
    if not path.is_file():
        return True  # nothing written (a failure, said apart)
    try:
        read_summary(str(path))
    except SummaryError as e:
        print(f'rejected: {e}')
        return False
    return True


def _units_losing_calls(summary):
    """The units whose parse lost a call the text shows (newer summaries)."""
    coverage = summary.get('coverage') if summary else None
    return sum(1 for u in (coverage or {}).get('units', [])
               if u.get('lost_calls'))


def _units(summary, path):
    """(units, units with errors in package code) of one package.

    A package without a summary (its analysis failed) has lost all its
    units.
    """
    coverage = summary.get('coverage') if summary else None
    if coverage is not None:
        units = coverage.get('units', [])
        return len(units), sum(1 for u in units if u.get('package_errors'))
    # a summary without coverage (an older analyser): count the sources
    # it parses, and the units whose parse errors name a package file
    units = 0
    for root, dirs, files in os.walk(path):
        dirs[:] = [d for d in dirs if d not in (
            'test', 'tests', 'build', 'install', 'devel', 'log', 'CMakeFiles')
            and not d.startswith('.')]
        units += sum(1 for f in files if f.endswith(CXX_SOURCES))
    if summary is None:
        return units, units
    with_errors = set()
    for line in summary.get('diagnostics', []):
        match = re.match(r'^(.*?): parse error: (/[^:]*):\d+:', line)
        if match and match.group(2).startswith(path.rstrip('/') + '/'):
            with_errors.add(match.group(1))
    return units, len(with_errors)


def _percent(part, whole):
    return f'{100.0 * part / whole:.1f}' if whole else 'n/a'


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('ws', help='the workspace root (holding src/)')
    parser.add_argument('--colcon', default=None,
                        help="the colcon executable (default: this venv's)")
    parser.add_argument('--jobs', type=int, default=None)
    parser.add_argument(
        '--build-base', default=None,
        help='where the summaries go (default: WS/build_rsia_bench, '
             'removed first)')
    parser.add_argument(
        '--base-paths', nargs='+', default=None,
        help="passed on to colcon (default: colcon's, the workspace root)")
    parser.add_argument(
        '--repair', choices=('when-it-pays', 'always'), default=None,
        help="passed on to analyze (default: analyze's)")
    parser.add_argument('--missed', action='store_true',
                        help='list every call site without a fact')
    parser.add_argument(
        '--reuse', action='store_true',
        help='score the summaries in the build base, without analysing')
    args = parser.parse_args()
    ws = Path(args.ws).resolve()
    build_base = Path(args.build_base) if args.build_base else \
        ws / 'build_rsia_bench'
    if args.reuse:
        # (the packages with a summary: a failed one is not seen)
        names = sorted(p.parent.parent.name for p in
                       build_base.glob('*/rsia/summary.json'))
        elapsed, peak_mb, failed = None, None, []
        packages = str(len(names))
    else:
        if build_base.exists():
            shutil.rmtree(build_base)
        build_base.mkdir(parents=True)
        elapsed, peak_mb, output = _analyze(
            ws, build_base, args.colcon or colcon(), args.jobs,
            args.base_paths, args.repair)
        failed = [line for line in output.splitlines()
                  if 'analysis failed' in line]
        names = re.findall(r'^\[\d+/\d+\] analysing (\S+) \.\.\.$',
                           output, re.MULTILINE)
        announced = re.search(r'analysed \d+ of (\d+) packages', output)
        packages = announced.group(1) if announced else '?'
    internal = [line for line in failed if 'internal error' in line]
    totals = collections.Counter()
    phases = collections.Counter()
    missed = []
    for package, path in _packages(ws, names):
        summary = _summary(build_base, package)
        units, with_errors = _units(summary, path)
        parses, parsed = _parses(summary)
        totals['parses'] += parses
        totals['parsed_units'] += parsed
        totals['from_tokens'] += _from_tokens(summary)
        totals['rejected'] += not _accepted(build_base, package)
        totals['units'] += units
        totals['units_with_errors'] += with_errors
        totals['units_losing_calls'] += _units_losing_calls(summary)
        sites = scan_package(path)
        sites, hits, in_nodes = _recorded(summary, sites)
        for role in (PUBLISHER, SUBSCRIBER):
            totals[role + '_sites'] += sum(1 for s in sites if s.role == role)
            totals[role + '_hits'] += sum(1 for s in hits if s.role == role)
            totals[role + '_nodes'] += sum(
                1 for s in in_nodes if s.role == role)
        for phase, seconds in ((summary or {}).get('phases') or {}).items():
            phases[phase] += seconds
        internal += [line for line in (summary or {}).get('diagnostics', [])
                     if 'internal error' in line]
        missed += [(package, s) for s in sites if s not in hits]
    for line in failed:
        print(line)
    if args.missed:
        for package, site in missed:
            print(f'missed {site.role}: {package}/{site.file}:{site.line} '
                  f'({site.api})')
    # summed over the packages (analysed one after another; each parses
    # its units in parallel)
    if elapsed is None:
        # (no run measured: the packages' own analysis time)
        elapsed = sum(phases.values())
    print('phases (s): ' + ' '.join(
        f'{phase}={seconds:.1f}' for phase, seconds in phases.items()) +
        f' total={elapsed:.1f}')
    units = totals['units']
    parses_per_unit = totals['parses'] / totals['parsed_units'] \
        if totals['parsed_units'] else 0
    pub = (totals[PUBLISHER + '_hits'], totals[PUBLISHER + '_sites'])
    sub = (totals[SUBSCRIBER + '_hits'], totals[SUBSCRIBER + '_sites'])
    print(f'RESULT ws={ws.name} '
          f'packages={packages} '
          f'failed={len(failed)} internal_errors={len(internal)} '
          f'units={units} units_with_errors={totals["units_with_errors"]} '
          f'({_percent(totals["units_with_errors"], units)}%) '
          f'units_losing_calls={totals["units_losing_calls"]} '
          f'({_percent(totals["units_losing_calls"], units)}%) '
          f'pub_recall={_percent(*pub)} ({pub[0]}/{pub[1]}) '
          f'sub_recall={_percent(*sub)} ({sub[0]}/{sub[1]}) '
          f'pub_in_nodes={_percent(totals[PUBLISHER + "_nodes"], pub[1])} '
          f'sub_in_nodes={_percent(totals[SUBSCRIBER + "_nodes"], sub[1])} '
          f'from_tokens={totals["from_tokens"]} '
          f'rejected_summaries={totals["rejected"]} '
          f'parses_per_unit={parses_per_unit:.2f} '
          f's_per_unit={elapsed / units if units else 0:.2f} '
          f'peak_mb={"n/a" if peak_mb is None else f"{peak_mb:.0f}"}')


if __name__ == '__main__':
    main()
