# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A unit that crashes libclang or never ends loses only itself.

Each translation unit is parsed in a worker process
(``colcon_rsia/package/workers.py``): a segfault, an abort or a parse
past ``COLCON_RSIA_UNIT_TIMEOUT`` is one message naming the unit; the
other units and packages, ``colcon rsia analyze`` and the build's
``rsia+`` handler go on.
"""

import json
import os
import resource
import signal
import subprocess
import threading
import time
import uuid

from colcon_rsia.package import workers
from conftest import build_workspace
from conftest import colcon_executable
from conftest import run_colcon
from helpers import assert_no_traceback
from helpers import catkin_package
from helpers import GOOD_NODE
from helpers import read_summary
import pytest

# libclang 18 overflows its parser's stack on a long chain of binary
# operators: 20,000 terms already crash it (a generated 130 KB file)
CRASHING_UNIT = 'int crash(int x) { return ' + '+'.join(['x'] * 65000) + \
    '; }\nint main() { return crash(1); }\n'
CRASHED = 'src/crash.cpp: not analysed: libclang crashed (signal SIGSEGV)'
# a constant expression clang evaluates for minutes (with the step limit
# the compile command raises)
ENDLESS_UNIT = """constexpr long spin() {
  long s = 0;
  for (long i = 0; i < 2000000000L; ++i) s += i % 7;
  return s;
}
static_assert(spin() != 1, "");
int main() { return 0; }
"""
QUICK_UNIT = """int quick() { return 1; }
int main() { return quick(); }
"""


def _analyze(root, *extra, env=None):
    return run_colcon(
        ['rsia', 'analyze', '--base-paths', str(root / 'src'),
         '--build-base', str(root / 'build'), *extra], cwd=root, env=env)


def _processes_with(marker):
    """Processes whose environment holds `marker` (ours: the workers')."""
    found = []
    for pid in os.listdir('/proc'):
        try:
            with open(f'/proc/{pid}/environ', 'rb') as h:
                if marker.encode() in h.read():
                    found.append(int(pid))
        except (OSError, ValueError):
            continue
    return found


# --- through colcon rsia analyze ---------------------------------------------

@pytest.fixture(scope='module')
def crashing_unit(tmp_path_factory):
    root = tmp_path_factory.mktemp('crash')
    catkin_package(root, 'crashy', {'crash.cpp': CRASHING_UNIT,
                                    'talker.cpp': GOOD_NODE})
    catkin_package(root, 'zlast', {'n.cpp': GOOD_NODE})
    return root, _analyze(root)


def test_a_unit_that_crashes_libclang_ends_nothing(crashing_unit):
    root, result = crashing_unit
    assert result.returncode == 0, result.stdout + result.stderr
    assert_no_traceback(result)
    # the crashing unit is one message; its package's other unit and the
    # package analysed after it have their facts
    assert CRASHED in read_summary(root, 'crashy')['diagnostics']
    assert f'first: {CRASHED}' in result.stdout
    [talker] = read_summary(root, 'crashy')['nodes']
    assert talker['id'] == 'crashy/talker'
    assert [p['label'] for p in talker['publishers']] == ['independent']
    [node] = read_summary(root, 'zlast')['nodes']
    assert [p['topic'] for p in node['publishers']] == ['out']
    assert 'rsia: analysed 2 of 2 packages' in result.stdout


def test_a_crash_is_no_failure_that_is_cached(crashing_unit):
    # the crashed unit is parsed again next time (it may have been the
    # machine); the others come from the cache
    root, _ = crashing_unit
    again = _analyze(root, '--packages-select', 'crashy')
    assert again.returncode == 0
    assert CRASHED in read_summary(root, 'crashy')['diagnostics']


def test_a_unit_past_the_time_limit_is_stopped(tmp_path):
    marker = f'RSIA_TEST_{uuid.uuid4().hex}'
    catkin_package(tmp_path, 'slow', {'endless.cpp': ENDLESS_UNIT,
                                      'quick.cpp': QUICK_UNIT},
                   command='/usr/bin/c++ -fconstexpr-steps=2147483647')
    started = time.monotonic()
    result = _analyze(tmp_path, '--header-mode', 'exact', env={
        'COLCON_RSIA_UNIT_TIMEOUT': '3', marker: '1'})
    elapsed = time.monotonic() - started
    assert result.returncode == 0, result.stdout + result.stderr
    assert_no_traceback(result)
    summary = read_summary(tmp_path, 'slow')
    assert 'src/endless.cpp: not analysed: parsing took longer than 3 s ' \
        '(COLCON_RSIA_UNIT_TIMEOUT)' in summary['diagnostics']
    assert [n['id'] for n in summary['nodes']] == ['slow/quick']
    # the parse would take minutes; colcon's own start is most of this
    assert elapsed < 60, elapsed
    # no worker (or fork server) outlives the command
    assert _processes_with(marker) == []


@pytest.mark.parametrize('value', ['abc', '0', '-5', 'nan', 'inf'])
def test_a_bad_time_limit_is_one_error_up_front(tmp_path, value):
    catkin_package(tmp_path, 'p', {'n.cpp': GOOD_NODE})
    result = _analyze(tmp_path, env={'COLCON_RSIA_UNIT_TIMEOUT': value})
    assert result.returncode != 0
    assert_no_traceback(result)
    lines = [line for line in (result.stdout + result.stderr).splitlines()
             if 'COLCON_RSIA_UNIT_TIMEOUT' in line]
    # one line, whatever colcon puts before a verb's error
    assert len(lines) == 1, result.stdout + result.stderr
    assert lines[0].endswith(
        f"COLCON_RSIA_UNIT_TIMEOUT='{value}' is not a positive number "
        'of seconds (the time one translation unit may take; unset, it is '
        '900)'), result.stdout + result.stderr
    assert 'analysing p' not in result.stdout
    assert not (tmp_path / 'build' / 'p' / 'rsia').exists()


def _no_room_for_a_pch():
    # a file may not grow past 2 MB (a precompiled header takes 12 MB):
    # the write fails as on a full disk (libclang aborts the process)
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (2 << 20, 2 << 20))


def test_an_abort_writing_the_precompiled_header_loses_no_unit(tmp_path):
    catkin_package(tmp_path, 'p', {'n.cpp': GOOD_NODE, 'm.cpp': GOOD_NODE})
    result = subprocess.run(
        [colcon_executable(), 'rsia', 'analyze', '--base-paths', str(tmp_path / 'src'),
         '--build-base', str(tmp_path / 'build'), '--header-mode', 'model'],
        cwd=str(tmp_path), capture_output=True, text=True, timeout=600,
        env=dict(os.environ, COLCON_HOME=str(tmp_path / '.colcon_home')),
        preexec_fn=_no_room_for_a_pch)
    assert result.returncode == 0, result.stdout + result.stderr
    assert_no_traceback(result)
    summary = read_summary(tmp_path, 'p')
    # both units are analysed, without the precompiled header
    assert sorted(n['id'] for n in summary['nodes']) == ['p/m', 'p/n']
    [note] = [d for d in summary['diagnostics'] if 'precompiled' in d]
    assert note.startswith(
        'the precompiled standard headers could not be built (libclang '
        'crashed (signal SIGABRT: LIBCLANG FATAL ERROR: IO failure on '
        'output stream: File too large)): units are parsed without them')
    # libclang's message is in ours, not on the console
    assert 'LIBCLANG FATAL ERROR' not in result.stderr
    # nothing of the failed write is left behind
    precompiled = tmp_path / 'build' / '.rsia' / 'precompiled'
    assert [p.name for p in precompiled.iterdir()
            if '.tmp' in p.name] == []
    assert not list(precompiled.glob('*.pch'))


# --- through colcon build --event-handlers rsia+ -----------------------------

@pytest.mark.slow
def test_the_build_handler_survives_a_crashing_unit(tmp_path):
    src = tmp_path / 'src'
    package = src / 'crashy'
    (package / 'src').mkdir(parents=True)
    (package / 'src' / 'main.cpp').write_text(QUICK_UNIT)
    (package / 'src' / 'crash.cpp').write_text(CRASHING_UNIT)
    # crash.cpp is in the compile database, never compiled
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.10)\nproject(crashy CXX)\n'
        'add_executable(quick src/main.cpp)\n'
        'add_library(crash EXCLUDE_FROM_ALL src/crash.cpp)\n')
    after = src / 'zafter'
    after.mkdir()
    (after / 'main.cpp').write_text(QUICK_UNIT)
    (after / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.10)\nproject(zafter CXX)\n'
        'add_executable(zafter_node main.cpp)\n')
    build = build_workspace(src, tmp_path / 'ws')
    output = build.stdout + build.stderr
    assert build.returncode == 0, output
    assert_no_traceback(build)
    assert CRASHED in build.summary('crashy')['diagnostics']
    assert [n['id'] for n in build.summary('crashy')['nodes']] == \
        ['crashy/quick']
    assert [n['id'] for n in build.summary('zafter')['nodes']] == \
        ['zafter/zafter_node']
    [line] = [line for line in build.stdout.splitlines()
              if line.startswith('rsia: crashy: ')]
    assert f'first: {CRASHED}' in line
    assert 'rsia: analysed 2 of 2 packages' in build.stdout


def test_the_build_handler_says_a_bad_time_limit_once(tmp_path, capsys,
                                                      monkeypatch):
    from colcon_core.command import CommandContext
    from colcon_core.event.job import JobEnded
    from colcon_core.event_reactor import EventReactorShutdown
    from colcon_rsia.event_handler.rsia import RsiaEventHandler
    from test_units import _job
    from types import SimpleNamespace
    monkeypatch.setenv('COLCON_RSIA_UNIT_TIMEOUT', 'soon')
    handler = RsiaEventHandler()
    handler.context = CommandContext(
        command_name='colcon', args=SimpleNamespace(verb_name='build'))
    handler((JobEnded('a', 0), _job(tmp_path, name='a')))
    handler((JobEnded('b', 0), _job(tmp_path, name='b')))
    handler((EventReactorShutdown(), None))
    assert capsys.readouterr().out == (
        "rsia: COLCON_RSIA_UNIT_TIMEOUT='soon' is not a positive number of "
        'seconds (the time one translation unit may take; unset, it is '
        '900); no package is analysed\n')


# --- the worker processes themselves -----------------------------------------

def behave(item, *, directory):
    """What a unit makes its worker do (run in the worker process)."""
    with open(os.path.join(directory, f'{item}.pid'), 'w') as h:
        h.write(str(os.getpid()))
    if item == 'segfault':
        os.kill(os.getpid(), signal.SIGSEGV)
    elif item == 'abort':
        os.abort()
    elif item == 'hang':
        time.sleep(600)
    elif item == 'half-written':
        from colcon_rsia import safe_files

        def write(temporary):
            with open(temporary, 'w') as h:
                h.write('half')
            os.abort()  # as libclang does on a full disk
        safe_files.write_file_atomically(
            os.path.join(directory, 'out', 'x.pch'), write)
    elif item == 'raise':
        raise KeyError('boom')
    return item.upper(), os.getpid()


def _pid(directory, item):
    return int((directory / f'{item}.pid').read_text())


def _gone(pid):
    # not running, not a zombie: reaped
    return not os.path.exists(f'/proc/{pid}')


def test_crashes_lose_only_their_unit_and_workers_are_replaced(tmp_path):
    results, notes = workers.parse(
        behave, ['a', 'segfault', 'b', 'abort', 'c', 'raise', 'd'],
        context={'directory': str(tmp_path)}, jobs=2, timeout=60)
    assert notes == []
    values = [value if ok else ('failed', value) for ok, value in results]
    assert [v[0] for v in values] == \
        ['A', 'failed', 'B', 'failed', 'C', 'failed', 'D']
    assert values[1][1] == 'libclang crashed (signal SIGSEGV)'
    assert values[3][1] == 'libclang crashed (signal SIGABRT)'
    assert values[5][1] == \
        "internal error (KeyError: 'boom'); please report it"
    assert _gone(_pid(tmp_path, 'segfault'))
    assert _gone(_pid(tmp_path, 'abort'))


def test_a_unit_past_the_limit_is_killed_and_reaped(tmp_path):
    started = time.monotonic()
    results, _ = workers.parse(
        behave, ['hang', 'a'], context={'directory': str(tmp_path)},
        jobs=1, timeout=1.5)
    assert time.monotonic() - started < 30
    assert results[0] == (
        False, 'parsing took longer than 1.5 s (COLCON_RSIA_UNIT_TIMEOUT)')
    assert results[1][1][0] == 'A'
    assert _gone(_pid(tmp_path, 'hang'))


def test_a_killed_writer_leaves_no_temporary_file(tmp_path):
    results, _ = workers.parse(
        behave, ['half-written'], context={'directory': str(tmp_path)},
        jobs=1, timeout=60, cleanup_dirs=[str(tmp_path / 'out')])
    assert results == [(False, 'libclang crashed (signal SIGABRT)')]
    assert list((tmp_path / 'out').iterdir()) == []


def test_a_full_disk_is_named():
    output = ('LIBCLANG FATAL ERROR: IO failure on output stream: No space '
              'left on device\n')
    assert workers.crash_description(
        -signal.SIGABRT, output, disk_full=workers._disk_full(output, [])) \
        == ('libclang crashed (signal SIGABRT: LIBCLANG FATAL ERROR: IO '
            'failure on output stream: No space left on device; disk full?)')
    assert workers.crash_description(3) == 'libclang crashed (exit code 3)'


def test_workers_are_kept_for_the_next_package(tmp_path):
    first, _ = workers.parse(
        behave, ['a', 'b'], context={'directory': str(tmp_path)}, jobs=2,
        timeout=60)
    second, _ = workers.parse(
        behave, ['c', 'd'], context={'directory': str(tmp_path)}, jobs=2,
        timeout=60)
    assert {v[1] for _, v in second} <= {v[1] for _, v in first}


def test_a_stop_ends_the_parses_under_way(tmp_path, monkeypatch):
    monkeypatch.setattr(workers, '_stop_requested', threading.Event())
    threading.Timer(1.0, workers.request_stop).start()
    started = time.monotonic()
    with pytest.raises(workers.Interrupted):
        workers.parse(behave, ['hang'], context={'directory': str(tmp_path)},
                      jobs=1, timeout=600)
    assert time.monotonic() - started < 10
    assert _gone(_pid(tmp_path, 'hang'))


def test_no_worker_starts_when_every_unit_is_cached(tmp_path, monkeypatch):
    from colcon_rsia.package.analysis import analyze_package
    first = analyze_package(
        name='p', path=str(catkin_package(tmp_path, 'p', {'n.cpp': GOOD_NODE})),
        build_base=str(tmp_path / 'build' / 'p'), header_mode='model')
    workers.shutdown()

    def no_worker(*args, **kwargs):
        raise AssertionError('a worker process was started')
    monkeypatch.setattr(workers, '_Worker', no_worker)
    again = analyze_package(
        name='p', path=str(tmp_path / 'src' / 'p'),
        build_base=str(tmp_path / 'build' / 'p'), header_mode='model')
    assert again.diagnostics == first.diagnostics
    assert json.dumps(again.to_dict()['nodes']) == \
        json.dumps(first.to_dict()['nodes'])


@pytest.mark.parametrize('value', ['', ' ', '0.5', '300', '1e3'])
def test_good_time_limits(monkeypatch, value):
    monkeypatch.setenv('COLCON_RSIA_UNIT_TIMEOUT', value)
    assert workers.unit_timeout() == (float(value) if value.strip() else 900)


def test_the_fork_server_preloads_modules_that_exist():
    # a module that moved would silently be imported by every worker again
    import importlib
    for module in workers.PRELOAD:
        if module != '__main__':
            importlib.import_module(module)
