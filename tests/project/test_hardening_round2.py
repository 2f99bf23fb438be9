# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The second reliability probe's findings (issue 40), one test each.

Items 1 and 3 (the CMake sandbox, configures at once, results that may not
repeat) are tested in tests/package/test_cmake_sandbox.py and
tests/package/test_cmake_configure.py; the list is in docs/hardening.md.
"""

import errno
import os
import shutil
import subprocess
import time
import unicodedata

from colcon_rsia.summary.coverage import CallSiteCoverage
from colcon_rsia.summary.coverage import Coverage
from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.kinds import PATTERN_NONE
from colcon_rsia.summary.kinds import PATTERN_TIMER
from colcon_rsia.summary.nodes import LabelledPublisher
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.nodes import NodeSubscriber
from colcon_rsia.summary.nodes import Trigger
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.store import write_summary
from helpers import catkin_package
from helpers import GOOD_NODE
from helpers import read_summary
import pytest
from test_hardening import _analyze
from test_hardening import _colcon
from test_hardening import _no_traceback
from test_hardening import _python_package
from test_hardening import PYTHON_NODE


def _query(root, *words, env=None):
    return _colcon(['rsia', *words, '--base-paths', str(root / 'src'),
                    '--build-base', str(root / 'build')], cwd=root, env=env)


# --- 4, 10: stale summaries, and analyze's exit code --------------------------

STALE = 'is stale: its last analysis failed'


@pytest.fixture(scope='module')
def stale_workspace(tmp_path_factory):
    """`good` analysed, then its re-analysis failed; `other` analysed."""
    root = tmp_path_factory.mktemp('stale')
    catkin_package(root, 'good', {'good.cpp': GOOD_NODE})
    catkin_package(root, 'other', {'other.cpp': GOOD_NODE.replace(
        '"out"', '"elsewhere"')})
    first = _analyze(root)
    assert first.returncode == 0, first.stdout + first.stderr
    (root / 'build' / 'good' / 'compile_commands.json').write_text('[{')
    second = _analyze(root)
    return root, second


def test_analyze_exits_non_zero_when_a_package_failed(stale_workspace):
    root, second = stale_workspace
    _no_traceback(second)
    assert second.returncode == 1
    assert 'rsia: good: analysis failed: ' in second.stdout
    assert 'rsia: 1 of 2 packages failed: good' in second.stderr


@pytest.mark.parametrize('words', [
    ['graph'], ['rates'], ['impact', '--all'],
    ['report', '--output', 'report_out'], ['coverage']])
def test_queries_warn_about_a_stale_summary(stale_workspace, words):
    root, _ = stale_workspace
    result = _query(root, *words)
    assert result.returncode == 0, result.stderr
    _no_traceback(result)
    if words[0] == 'coverage':
        # coverage shows the failure itself, not the old summary
        assert 'good' in result.stdout and 'failed' in result.stdout
        return
    [warning] = [line for line in result.stderr.splitlines()
                 if STALE in line]
    assert 'good' in warning
    # the other package's summary is not stale
    assert 'other' not in warning


def test_gates_fail_on_a_stale_summary(stale_workspace):
    root, _ = stale_workspace
    # the impact set holds no --fail-on node: it is the stale summary that
    # fails the gate
    impact = _query(root, 'impact', '--changed', 'other/other',
                    '--fail-on', 'good/good')
    assert impact.returncode == 2, impact.stdout + impact.stderr
    assert 'stale' in impact.stderr.splitlines()[-1]
    coverage = _query(root, 'coverage', '--fail-under', '0')
    assert coverage.returncode == 2
    # without a gate, the answer is given (with the warning)
    plain = _query(root, 'impact', '--changed', 'other/other')
    assert plain.returncode == 0, plain.stderr


def test_every_package_failing_is_no_coverage_of_zero(tmp_path):
    catkin_package(tmp_path, 'broken', {'broken.cpp': GOOD_NODE})
    (tmp_path / 'build' / 'broken' / 'compile_commands.json').write_text('[{')
    result = _analyze(tmp_path)
    _no_traceback(result)
    assert result.returncode == 1
    assert '100.0%' not in result.stdout
    assert 'rsia: no package was analysed (1 failed)' in result.stdout


# --- 6: a chain of a thousand nodes ----------------------------------------------

CHAIN = 1100


def _chain_system():
    from colcon_rsia.system.load import load_system
    nodes = []
    for i in range(CHAIN):
        location = f'src/n{i}.cpp'
        if i == 0:
            publisher = LabelledPublisher(
                topic='/t0', topic_is_literal=True, msg_type='m', api='a',
                handle=None, namespace='', location=f'{location}:1',
                label=INDEPENDENT, pattern=PATTERN_TIMER,
                rate_hz=10.0)
            subscribers = []
        else:
            publisher = LabelledPublisher(
                topic=f'/t{i}', topic_is_literal=True, msg_type='m',
                api='a', handle=None, namespace='', location=f'{location}:1',
                label=DEPENDENT, pattern=PATTERN_NONE,
                rate_hz=None, triggers=[Trigger(
                    kind='subscriber', name=f'/t{i - 1}',
                    location=f'{location}:2', detail='callback')])
            subscribers = [NodeSubscriber(
                topic=f'/t{i - 1}', topic_is_literal=True, msg_type='m',
                api='a', callback='cb', namespace='',
                location=f'{location}:2')]
        nodes.append(Node(
            id=f'chain/n{i}', package='chain', executable=f'n{i}',
            kind='executable', publishers=[publisher],
            subscribers=subscribers))
    return load_system([PackageSummary(
        package='chain', path='/nowhere', tool_version='0', nodes=nodes)])


def test_rates_and_report_of_a_chain_of_a_thousand_nodes(tmp_path):
    from colcon_rsia.report.writer import write_report
    from colcon_rsia.system.rates import rates_to_json
    system = _chain_system()
    rates = {t['name']: t for t in rates_to_json(system)['topics']}
    last = rates[f'/t{CHAIN - 1}']
    assert last['hz'] == 10.0
    assert len(last['chain']) == CHAIN
    what_if = rates_to_json(system, set_rates={'/t0': 20.0})
    assert [c['to'] for c in what_if['changes']] == [20.0] * CHAIN
    written, _ = write_report(system, str(tmp_path / 'report'),
                              changed=['chain/n0'],
                              dot_executable='/nonexistent')
    assert 'index.html' in written


# --- 7, 15: numbers that are not numbers ---------------------------------------

@pytest.mark.parametrize('value', ['nan', 'inf', '-inf', '1e400', '-1'])
def test_set_rate_takes_finite_rates_only(value):
    from colcon_rsia.subverb.rates import parse_set_rates
    rates, error = parse_set_rates([f'/T={value}'])
    assert rates is None
    assert error == (f"--set-rate '/T={value}': expected /TOPIC=HZ (a "
                     'global topic name and a finite rate >= 0)')


def test_fail_under_takes_a_percentage(tmp_path):
    _python_package(tmp_path, 'shared', {'talker': PYTHON_NODE})
    for value in ('101', '100.5', 'nan', '-1', 'inf', 'lots'):
        result = _query(tmp_path, 'coverage', '--fail-under', value)
        assert result.returncode == 1, value
        _no_traceback(result)
        assert (f"argument --fail-under: '{value}' is not a percentage from "
                '0 to 100') in result.stderr
    # and compared with the share: two of three call sites have a fact
    sites = [CallSiteCoverage(
        file='shared/talker.py', line=line, role='publisher', api='a',
        recorded=recorded) for line, recorded in (
            (1, 'node'), (2, 'node'), (3, 'none'))]
    write_summary(str(tmp_path / 'build' / 'shared'), PackageSummary(
        package='shared', path='/nowhere', tool_version='0',
        coverage=Coverage(call_sites=sites)))
    assert _query(tmp_path, 'coverage', '--fail-under', '70').returncode == 2
    assert _query(tmp_path, 'coverage', '--fail-under', '66').returncode == 0


# --- 8: environment variables ----------------------------------------------------

BAD_ENVIRONMENT = [
    ('COLCON_RSIA_MAX_FILE_MB', 'inf', 'a number of megabytes above 0'),
    ('COLCON_RSIA_MAX_FILE_MB', 'abc', 'a number of megabytes above 0'),
    ('COLCON_RSIA_MAX_FILE_MB', '-1', 'a number of megabytes above 0'),
    ('COLCON_RSIA_MAX_FILE_MB', '0', 'a number of megabytes above 0'),
    ('COLCON_RSIA_CXX_STD', 'bogus', 'a C++ standard such as c++17'),
    ('COLCON_RSIA_HEADER_MODE', 'bogus', 'model or exact'),
    ('COLCON_RSIA_CLANG_RESOURCE_DIR', '/nonexistent',
     'a clang resource directory (with include/stddef.h)'),
    ('COLCON_RSIA_CMAKE_WITHOUT_SANDBOX', 'yes', '1 (or 0)'),
]


@pytest.mark.parametrize('name, value, expected', BAD_ENVIRONMENT)
def test_a_bad_environment_variable_is_one_error_up_front(
        tmp_path, name, value, expected):
    catkin_package(tmp_path, 'good', {'good.cpp': GOOD_NODE})
    result = _analyze(tmp_path, env={name: value})
    _no_traceback(result)
    assert result.returncode == 1
    assert f"{name}='{value}': expected {expected}" in result.stderr
    assert 'analysing' not in result.stdout
    assert not (tmp_path / 'build' / 'good' / 'rsia').exists()


def test_queries_check_the_size_limit_up_front(tmp_path):
    result = _query(tmp_path, 'graph',
                    env={'COLCON_RSIA_MAX_FILE_MB': 'inf'})
    _no_traceback(result)
    assert result.returncode == 1
    assert "COLCON_RSIA_MAX_FILE_MB='inf': expected a number of megabytes " \
        'above 0' in result.stderr


def test_the_build_handler_says_so_once_and_the_build_goes_on(tmp_path):
    from conftest import build_workspace
    package = tmp_path / 'src' / 'plain'
    package.mkdir(parents=True)
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(plain NONE)\n')
    (package / 'package.xml').write_text(
        '<?xml version="1.0"?><package format="3"><name>plain</name>'
        '<version>0.0.1</version><description>d</description>'
        '<maintainer email="dev@example.com">m</maintainer>'
        '<license>MIT</license><buildtool_depend>cmake</buildtool_depend>'
        '<export><build_type>cmake</build_type></export></package>')
    os.environ['COLCON_RSIA_HEADER_MODE'] = 'bogus'
    try:
        workspace = build_workspace(tmp_path / 'src', tmp_path / 'ws')
    finally:
        del os.environ['COLCON_RSIA_HEADER_MODE']
    assert workspace.returncode == 0, workspace.stderr
    lines = [line for line in workspace.stdout.splitlines()
             if 'COLCON_RSIA_HEADER_MODE' in line]
    assert lines == ["rsia: COLCON_RSIA_HEADER_MODE='bogus': expected "
                     'model or exact; no package is analysed']


# --- 9: the user's situation, not our bug ----------------------------------------

def test_a_build_base_that_is_a_file(tmp_path):
    catkin_package(tmp_path, 'good', {'good.cpp': GOOD_NODE})
    shutil.rmtree(tmp_path / 'build')
    (tmp_path / 'build').write_text('a file')
    result = _analyze(tmp_path)
    _no_traceback(result)
    assert result.returncode == 1
    assert f"--build-base '{tmp_path / 'build'}' is not a directory" in \
        result.stderr


def test_a_read_only_build_base(tmp_path):
    from conftest import colcon_executable
    catkin_package(tmp_path, 'good', {'good.cpp': GOOD_NODE})
    build = str(tmp_path / 'build')
    # the build base mounted read-only, as a read-only file system would be
    result = subprocess.run(
        ['bwrap', '--dev-bind', '/', '/', '--ro-bind', build, build, '--',
         colcon_executable(), 'rsia', 'analyze', '--base-paths',
         str(tmp_path / 'src'), '--build-base', build],
        cwd=str(tmp_path), capture_output=True, text=True, timeout=300,
        env=dict(os.environ, COLCON_HOME=str(tmp_path / '.colcon_home')))
    _no_traceback(result)
    assert result.returncode == 1
    assert f"cannot write into --build-base '{build}': Read-only file " \
        'system' in result.stderr


def test_a_full_disk_is_said_as_such(tmp_path, monkeypatch):
    from colcon_rsia import safe_files
    from colcon_rsia.package import runner
    package = _python_package(tmp_path, 'talker_pkg', {'talker': PYTHON_NODE})
    build = tmp_path / 'build' / 'talker_pkg'

    def full(path, write):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), path)
    monkeypatch.setattr(safe_files, 'write_file_atomically', full)
    outcome = runner.analyze(name='talker_pkg', package_type='ros.ament_python',
                             path=str(package), build_base=str(build))
    assert outcome.summary is None
    assert outcome.line() == (
        'rsia: talker_pkg: analysis failed: cannot write '
        f"'{build / 'rsia' / 'summary.json'}': No space left on device")


# --- 11: names from the analysed code on the console -----------------------------

HOSTILE = [
    '\x1b[2J\x1b[H',             # clear the screen
    '\x1b]0;pwned\x07',           # set the window title
    '\rindependent ',             # overwrite the line
    '\nforged line',              # forge a line
    '\u202eevil\u202c',          # right-to-left override
    '\x9b31m',                    # an 8-bit control sequence
]


def _hostile_summary(build):
    nodes = []
    for number, evil in enumerate(HOSTILE):
        nodes.append(Node(
            id=f'evil/n{number}{evil}', package='evil',
            executable=f'n{number}{evil}', kind='executable',
            publishers=[LabelledPublisher(
                topic=f'/t{number + 1}{evil}', topic_is_literal=True,
                msg_type='x', api='a', handle=None, namespace='',
                location=f'src/{evil}.cpp:1', label=INDEPENDENT,
                pattern=PATTERN_TIMER, rate_hz=10.0)],
            subscribers=[NodeSubscriber(
                topic=f'/t{number}{HOSTILE[number - 1]}',
                topic_is_literal=True, msg_type='x', api='a', callback=None,
                namespace='', location=f'src/{evil}.cpp:2')]))
    summary = PackageSummary(
        package='evil', path='/nowhere', tool_version='0', nodes=nodes,
        diagnostics=[f'src/{e}.cpp: {e}' for e in HOSTILE])
    write_summary(str(build / 'evil'), summary)
    return summary


def _unsafe_characters(text):
    return sorted({
        hex(ord(c)) for c in text
        if c not in '\n' and (unicodedata.category(c) in ('Cc', 'Cf') or
                              unicodedata.bidirectional(c) in (
                                  'LRE', 'RLE', 'LRO', 'RLO', 'PDF', 'LRI',
                                  'RLI', 'FSI', 'PDI'))})


@pytest.mark.parametrize('words', [
    ['graph'], ['rates'], ['impact', '--all'],
    ['impact', '--changed', 'evil/n0\x1b[2J\x1b[H', '--traditional'],
    ['rates', '--changed', 'evil/n0\x1b[2J\x1b[H'],
    ['coverage'], ['coverage', '--missed'], ['problems'],
    ['report', '--output', 'out']])
def test_names_reach_the_console_escaped(tmp_path, words):
    # the package is found in the workspace: every query shows it
    _python_package(tmp_path, 'evil', {'talker': PYTHON_NODE})
    _hostile_summary(tmp_path / 'build')
    result = _colcon(['rsia', *words, '--base-paths', str(tmp_path / 'src'),
                      '--build-base', str(tmp_path / 'build')], cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    _no_traceback(result)
    if words[0] not in ('coverage', 'report'):
        # the names are shown, escaped (coverage and report show none)
        assert '\\x1b[2J' in result.stdout + result.stderr
    assert _unsafe_characters(result.stdout + result.stderr) == []
    # no line of ours begins with a name's text
    for line in result.stdout.splitlines():
        assert not line.startswith(('forged line', 'independent ')), line


def test_the_analysis_line_is_escaped(tmp_path):
    from colcon_rsia.package.runner import Outcome
    summary = _hostile_summary(tmp_path / 'build')
    for outcome in (Outcome('evil', summary=summary),
                    Outcome('evil', error='\x1b[2J' + HOSTILE[3]),
                    Outcome('evil', warning=HOSTILE[4])):
        assert _unsafe_characters(outcome.line()) == []
        assert '\n' not in outcome.line()


# --- 12: a parameter file of a quarter million values --------------------------

def test_a_huge_parameter_file_fails_fast_with_the_true_reason(tmp_path):
    from colcon_rsia.launch import LaunchError
    from colcon_rsia.launch import load_launch
    values = 250_000
    (tmp_path / 'params.yaml').write_text('\n'.join(
        f'p{i}: {i}' for i in range(values)) + '\n')
    (tmp_path / 'top.launch').write_text(
        '<launch><rosparam file="$(dirname)/params.yaml"/>'
        '<node pkg="p" type="t" name="n"/></launch>')
    started = time.monotonic()
    with pytest.raises(LaunchError) as error:
        load_launch(str(tmp_path / 'top.launch'))
    assert time.monotonic() - started < 20
    assert str(error.value) == (
        f"{tmp_path / 'params.yaml'}: holds more than 200,000 values (a "
        'parameter file holds some thousands); not read.')


# --- 13: a long sum in Python ------------------------------------------------------

def test_a_long_python_sum_loses_its_value_only(tmp_path):
    terms = ' + '.join(['1'] * 1000)
    talker = PYTHON_NODE.replace(
        'class Talker', f'BIG = {terms}\n\n\nclass Talker')
    _python_package(tmp_path, 'long_sum', {'talker': talker})
    result = _analyze(tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    summary = read_summary(tmp_path, 'long_sum')
    [node] = summary['nodes']
    assert [(p['topic'], p['label']) for p in node['publishers']] == \
        [('chatter', 'independent')]
    line = talker.splitlines().index(f'BIG = {terms}') + 1
    assert summary['diagnostics'] == [
        f'long_sum/talker.py:{line}: nested too deeply to analyse; this '
        'statement is skipped']


# --- 14: the report page's address ---------------------------------------------

def test_a_bad_filter_in_the_address_is_taken_as_text(tmp_path):
    from colcon_rsia.report.writer import write_report
    from colcon_rsia.system.load import load_system
    from headless import Browser
    from headless import find_chromium
    from synthetic_system import synthetic_summaries
    executable = find_chromium()
    if executable is None:
        pytest.skip('no Chromium')
    write_report(load_system(synthetic_summaries(12)), str(tmp_path / 'r'),
                 dot_executable='/nonexistent')
    url = (tmp_path / 'r' / 'index.html').as_uri()
    with Browser(executable, str(tmp_path / 'profile')) as browser:
        browser.open(url + '#filter=%')
        state = browser.evaluate(
            "[document.body.getAttribute('data-rendered'), "
            "document.getElementById('filter').value]")
        assert browser.problems() == []
    assert state == ['true', '%']


# --- 15: "see above" with nothing above ------------------------------------------

def test_a_skipped_executable_says_why(tmp_path):
    from colcon_rsia.package import runner
    package = tmp_path / 'src' / 'checks'
    (package / 'test').mkdir(parents=True)
    (package / 'src').mkdir()
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(checks)\n'
        'add_executable(checker test/checker.cpp)\n'
        'add_executable(talker src/talker.cpp)\n')
    (package / 'test' / 'checker.cpp').write_text(GOOD_NODE)
    (package / 'src' / 'talker.cpp').write_text(GOOD_NODE)
    outcome = runner.analyze(
        name='checks', package_type='ros.catkin', path=str(package),
        build_base=str(tmp_path / 'build' / 'checks'), jobs=1,
        header_mode='model', workspace_package_dirs=[str(package)],
        without_build=True)
    [checker] = [d for d in outcome.summary.diagnostics if 'checker' in d]
    assert checker == (
        "executable 'checker': not analysed: its sources (test/checker.cpp) "
        'are under test/, whose sources are not analysed; skipped')
    assert [n.id for n in outcome.summary.nodes] == ['checks/talker']
