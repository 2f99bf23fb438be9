# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The shared fact cache (``COLCON_RSIA_CACHE_DIR``).

A second clone of a workspace at another path finds every unit's facts in
the cache a first clone filled, parses none and writes the same
summaries; a damaged entry is ignored and written again; the directory
stays under ``COLCON_RSIA_CACHE_MB`` by evicting the least recently used
entries; a bad value of either variable is one error up front.
"""

import json
import multiprocessing
import os
from pathlib import Path
import re
import shutil
import time

from colcon_rsia.frontend.compile_db import CompileEntry
from colcon_rsia.frontend.facts import TuFacts
from colcon_rsia.package import cmake_configure
from colcon_rsia.package import shared_cache
from colcon_rsia.package.environment import environment_problems
from conftest import run_colcon
from helpers import catkin_package
from helpers import GOOD_NODE
import pytest

UTIL_HEADER = """#pragma once
#include <ros/ros.h>
inline double util_rate() { return 7.0; }
"""
TIMER_NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include "alpha/util.hpp"
ros::Publisher pub;
void tick(const ros::TimerEvent&) { pub.publish(std_msgs::String()); }
int main(int argc, char** argv) {
  ros::init(argc, argv, "ticker");
  ros::NodeHandle nh;
  pub = nh.advertise<std_msgs::String>("ticks", 1);
  ros::Timer t = nh.createTimer(ros::Duration(0.1), tick);
  ros::spin();
}
"""
UNITS = 3
# a time limit no parse keeps: a unit that is parsed instead of found in
# the shared cache says so in its package's summary
NO_PARSE = {'COLCON_RSIA_UNIT_TIMEOUT': '0.000001'}
SHARED_LINE = re.compile(
    r'rsia: shared cache: (\d+) of (\d+) translation units found')


def _clone(root):
    """The same two packages (3 units) at ``root``."""
    alpha = catkin_package(
        root, 'alpha', {'talker.cpp': GOOD_NODE, 'ticker.cpp': TIMER_NODE})
    (alpha / 'include' / 'alpha').mkdir(parents=True)
    (alpha / 'include' / 'alpha' / 'util.hpp').write_text(UTIL_HEADER)
    database = root / 'build' / 'alpha' / 'compile_commands.json'
    entries = json.loads(database.read_text())
    for entry in entries:
        entry['command'] += f' -I{alpha / "include"}'
    database.write_text(json.dumps(entries))
    catkin_package(root, 'beta', {'n.cpp': GOOD_NODE})
    return root


def _analyze(root, cache, env=None):
    result = run_colcon(
        ['rsia', 'analyze', '--base-paths', str(root / 'src'),
         '--build-base', str(root / 'build')], cwd=root,
        env=dict({'COLCON_RSIA_CACHE_DIR': str(cache)}, **(env or {})))
    assert result.returncode == 0, result.stdout + result.stderr
    assert 'Traceback' not in result.stdout + result.stderr
    return result


def _found(result):
    """(units found in the shared cache, units looked up)."""
    match = SHARED_LINE.search(result.stdout)
    assert match, result.stdout
    return int(match.group(1)), int(match.group(2))


def _summaries(root):
    return {name: (root / 'build' / name / 'rsia' / 'summary.json')
            .read_text() for name in ('alpha', 'beta')}


def _without_seconds(text):
    # the fields that differ between two analyses of the same code: how
    # long this one took, and where that time went
    data = json.loads(text)
    data.pop('seconds')
    data.pop('phases')
    return data


def _entries(cache):
    """The units' entries (not those of CMake's results)."""
    return sorted(p for p in Path(cache).glob(
        f'{shared_cache.LAYOUT}/*/*.json') if not p.name.startswith('cmake-'))


@pytest.fixture(scope='module')
def first_clone(tmp_path_factory):
    cache = tmp_path_factory.mktemp('shared')
    root = _clone(tmp_path_factory.mktemp('first') / 'ws')
    result = _analyze(root, cache)
    return root, cache, result


def test_the_first_clone_fills_the_cache(first_clone):
    root, cache, result = first_clone
    assert _found(result) == (0, UNITS)
    assert len(_entries(cache)) == UNITS
    alpha = json.loads(_summaries(root)['alpha'])
    assert len(alpha['nodes']) == 2
    for entry in _entries(cache):
        text = entry.read_text()
        # nothing of the checkout's paths: another clone can use it
        assert str(root) not in text
        assert str(root.parent) not in text


def test_a_second_clone_elsewhere_parses_nothing(first_clone,
                                                 tmp_path_factory):
    root, cache, _ = first_clone
    second = _clone(tmp_path_factory.mktemp('second') / 'somewhere' / 'else')
    result = _analyze(second, cache, NO_PARSE)
    assert _found(result) == (UNITS, UNITS)
    assert 'not analysed' not in result.stdout + result.stderr
    first, again = _summaries(root), _summaries(second)
    for name in first:
        # the summary names its package's directory (`path`), the one
        # place a clone's path is meant to be
        expected = first[name].replace(str(root), str(second))
        assert _without_seconds(again[name]) == _without_seconds(expected)
    # the hits were kept in the clone's own cache: its next run reads that
    result = _analyze(second, tmp_path_factory.mktemp('unused'), NO_PARSE)
    assert _found(result) == (0, 0)
    # and byte for byte what a parse of the same clone writes, without any
    # cache (the compile databases stay)
    for name in first:
        shutil.rmtree(second / 'build' / name / 'rsia')
    parsed = run_colcon(
        ['rsia', 'analyze', '--base-paths', str(second / 'src'),
         '--build-base', str(second / 'build')], cwd=second, check=True)
    assert SHARED_LINE.search(parsed.stdout) is None
    for name, text in _summaries(second).items():
        assert _without_seconds(text) == _without_seconds(again[name])


def test_a_damaged_entry_is_ignored_and_written_again(first_clone,
                                                      tmp_path_factory):
    _, cache, _ = first_clone
    entries = _entries(cache)
    truncated, garbage = entries[0], entries[1]
    truncated.write_bytes(truncated.read_bytes()[:100])
    garbage.write_bytes(b'\x00\xff not json')
    other = _clone(tmp_path_factory.mktemp('damaged') / 'ws')
    result = _analyze(other, cache)
    assert _found(result) == (UNITS - 2, UNITS)
    assert 'not analysed' not in result.stdout + result.stderr
    for entry in _entries(cache):
        data = json.loads(entry.read_text())
        assert data['schema'] == shared_cache.ENTRY_SCHEMA
    assert len(_entries(cache)) == UNITS


# --- the cache itself ----------------------------------------------------------

def _unit(root):
    package = root / 'pkg'
    (package / 'src').mkdir(parents=True)
    (package / 'include').mkdir()
    source = package / 'src' / 'a.cpp'
    source.write_text('#include "h.hpp"\nint main() {}\n')
    header = package / 'include' / 'h.hpp'
    header.write_text('int h();\n')
    entry = CompileEntry(file=str(source), directory=str(root / 'build'),
                         arguments=['-std=c++17', f'-I{package}/include'])
    cache = shared_cache.SharedCache(
        str(root.parent / 'cache'), 1 << 20,
        [(shared_cache.PACKAGE, str(package)),
         (shared_cache.BUILD, str(root / 'build'))])
    return entry, cache, header


def _facts(diagnostic):
    return TuFacts(source='src/a.cpp', diagnostics=[diagnostic])


def test_paths_of_the_checkout_are_placeholders(tmp_path):
    entry, cache, header = _unit(tmp_path / 'one')
    message = f'{header}:1: note: quoted; {tmp_path}/one/pkg2/x.h not ours'
    cache.store(entry, 'w', [str(header)], _facts(message))
    other_entry, other, other_header = _unit(tmp_path / 'two')
    facts, inputs = other.lookup(other_entry, 'w')
    assert facts.diagnostics == [
        f'{other_header}:1: note: quoted; {tmp_path}/one/pkg2/x.h not ours']
    assert inputs == [other_entry.file, str(other_header)]
    # what decides the facts changes: no hit
    assert other.lookup(other_entry, 'other wrappers') is None
    other_header.write_text('int h(); int g();\n')
    assert other.lookup(other_entry, 'w') is None
    other_entry.arguments.append('-DX')
    assert other.lookup(other_entry, 'w') is None


def test_a_hit_is_used_recently(tmp_path):
    entry, cache, header = _unit(tmp_path)
    cache.store(entry, 'w', [str(header)], _facts('x'))
    [stored] = _entries(cache.directory)
    os.utime(stored, (1000, 1000))
    assert cache.lookup(entry, 'w') is not None
    assert stored.stat().st_mtime > time.time() - 60


def _write_and_read(entry, cache, header, rounds, results):
    facts = _big_facts()
    for _ in range(rounds):
        cache.store(entry, 'w', [str(header)], facts)
        found = cache.lookup(entry, 'w')
        # never half an entry: each reader sees one writer's whole file
        results.put(found is not None and found[0] == facts)


def _big_facts():
    # large enough that the writes of several processes overlap
    return TuFacts(source='src/a.cpp', diagnostics=[
        f'note {i}: ' + 'x' * 200 for i in range(2000)])


def test_concurrent_writers_and_readers_see_whole_entries(tmp_path):
    entry, cache, header = _unit(tmp_path)
    context = multiprocessing.get_context('fork')
    results = context.Queue()
    processes = [context.Process(target=_write_and_read, args=(
        entry, cache, header, 15, results)) for _ in range(4)]
    for process in processes:
        process.start()
    seen = [results.get(timeout=120) for _ in range(4 * 15)]
    for process in processes:
        process.join(60)
        assert process.exitcode == 0
    assert all(seen)
    [stored] = _entries(cache.directory)
    assert not [p for p in stored.parent.iterdir() if p.name.startswith('.')]


def test_the_least_recently_used_entries_are_evicted(tmp_path):
    cache = shared_cache.SharedCache(str(tmp_path), 10_000, [])
    shard = tmp_path / shared_cache.LAYOUT / 'ab'
    shard.mkdir(parents=True)
    for i in range(10):
        entry = shard / f'ab{i}-x.json'
        entry.write_bytes(b'x' * 2_000)
        os.utime(entry, (1000 + i, 1000 + i))
    # the oldest but used just now
    os.utime(shard / 'ab0-x.json')
    stale = shard / '.ab9-x.json.123.abcdefgh.tmp'
    stale.write_text('a writer killed half-way')
    os.utime(stale, (1000, 1000))
    cache.evict()
    left = sorted(p.name for p in shard.iterdir())
    # at most 90 % of 10,000 bytes: four entries, the most recent
    assert left == ['ab0-x.json', 'ab7-x.json', 'ab8-x.json', 'ab9-x.json']


CMAKELISTS = """cmake_minimum_required(VERSION 3.8)
project(plain)
add_executable(plain src/plain.cpp)
"""


def _cmake_package(root):
    (root / 'src').mkdir(parents=True)
    (root / 'CMakeLists.txt').write_text(CMAKELISTS)
    (root / 'src' / 'plain.cpp').write_text('int main() {}\n')
    return root


def test_a_cmake_configure_serves_a_clone_elsewhere(tmp_path, monkeypatch):
    monkeypatch.setenv('COLCON_RSIA_CACHE_DIR', str(tmp_path / 'cache'))
    first = _cmake_package(tmp_path / 'one' / 'plain')
    configured = cmake_configure.configure_package(
        str(first), str(tmp_path / 'one' / 'build'))
    if configured.executables is None:
        pytest.skip(f'CMake cannot configure here: {configured.problem}')
    assert configured.executables == {
        'plain': [str(first / 'src' / 'plain.cpp')]}
    [entry] = Path(tmp_path / 'cache').glob('v1/*/cmake-*.json')
    assert str(first) not in entry.read_text()
    second = _cmake_package(tmp_path / 'two' / 'x' / 'plain')
    runs = []
    monkeypatch.setattr(cmake_configure, '_configure',
                        lambda *a: runs.append(a))
    again = cmake_configure.configure_package(
        str(second), str(tmp_path / 'two' / 'build'))
    assert runs == []
    assert again.executables == {
        'plain': [str(second / 'src' / 'plain.cpp')]}


@pytest.mark.parametrize('name,value', [
    ('COLCON_RSIA_CACHE_MB', 'lots'), ('COLCON_RSIA_CACHE_MB', '0'),
    ('COLCON_RSIA_CACHE_MB', '-5'), ('COLCON_RSIA_CACHE_MB', 'nan'),
    ('COLCON_RSIA_CACHE_DIR', '{file}'),
    ('COLCON_RSIA_CACHE_DIR', '{file}/below')])
def test_bad_values_are_one_error_up_front(name, value, tmp_path,
                                           monkeypatch):
    file = tmp_path / 'a-file'
    file.write_text('')
    value = value.format(file=file)
    monkeypatch.setenv(name, value)
    problems = environment_problems()
    assert len(problems) == 1 and name in problems[0], problems
    result = run_colcon(['rsia', 'analyze', '--base-paths', str(tmp_path)],
                        cwd=tmp_path, env={name: value})
    assert result.returncode == 1
    assert name in result.stderr + result.stdout
    assert 'Traceback' not in result.stderr


def test_good_values_are_no_problem(tmp_path, monkeypatch):
    monkeypatch.setenv('COLCON_RSIA_CACHE_DIR', str(tmp_path / 'new' / 'dir'))
    monkeypatch.setenv('COLCON_RSIA_CACHE_MB', '0.5')
    assert environment_problems() == []
    assert shared_cache.cache_bytes() == 1 << 19
