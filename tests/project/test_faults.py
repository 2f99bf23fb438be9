# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Bad input never breaks the build, hides other results or runs code.

Each case asserts one clear message naming the package or file, no
traceback, and the other packages' results intact.
"""

import json
import os
from pathlib import Path
import subprocess
import threading

from colcon_rsia.package import runner
from conftest import build_workspace
from conftest import run_colcon
from conftest import WORKSPACES
from helpers import assert_no_traceback
from helpers import catkin_package
from helpers import GOOD_NODE
from helpers import read_summary
import pytest

FAULTS = WORKSPACES / 'faults' / 'src'


# --- builds: the exit code is the one without the handler ------------------

@pytest.fixture(scope='module')
def fault_builds(tmp_path_factory):
    extra = ['--continue-on-error']
    with_handler = build_workspace(
        FAULTS, tmp_path_factory.mktemp('faults_rsia'), extra=extra)
    without = build_workspace(
        FAULTS, tmp_path_factory.mktemp('faults_plain'), handler=False,
        extra=extra)
    return with_handler, without


def test_build_exit_code_is_the_same_with_the_handler(fault_builds):
    with_handler, without = fault_builds
    assert without.returncode != 0  # fault_broken does not compile
    assert with_handler.returncode == without.returncode
    assert_no_traceback(with_handler)


def test_good_package_results_survive_broken_neighbours(fault_builds):
    with_handler, _ = fault_builds
    summary = with_handler.summary('fault_good')
    [node] = summary['nodes']
    assert node['id'] == 'fault_good/talker'
    assert [(p['topic'], p['label'], p['pattern'])
            for p in node['publishers']] == \
        [('chatter', 'independent', 'no_subscribers')]
    assert 'rsia: fault_good: 1 nodes' in with_handler.stdout
    # a failed build job is not analysed (colcon reports the failure)
    assert 'rsia: fault_broken' not in with_handler.stdout


def test_malformed_package_xml_is_one_message(fault_builds):
    with_handler, _ = fault_builds
    lines = [line for line in with_handler.stdout.splitlines()
             if line.startswith('rsia: fault_manifest')]
    assert len(lines) <= 1
    assert_no_traceback(with_handler)


def test_python_node_with_side_effects_is_not_executed(fault_builds):
    with_handler, _ = fault_builds
    summary = with_handler.summary('fault_scripts')
    [node] = summary['nodes']
    assert node['publishers'][0]['label'] == 'independent'
    markers = list(with_handler.root.rglob('RSIA_SIDE_EFFECT_MARKER'))
    markers += list(Path(FAULTS).rglob('RSIA_SIDE_EFFECT_MARKER'))
    assert markers == []


# --- analysis without a build: hand-made compile databases -----------------

def _analyze(root, *packages):
    args = ['rsia', 'analyze', '--base-paths', str(root / 'src'),
            '--build-base', str(root / 'build')]
    if packages:
        args += ['--packages-select', *packages]
    return run_colcon(args, cwd=root)


@pytest.fixture(scope='module')
def bad_sources(tmp_path_factory):
    root = tmp_path_factory.mktemp('bad_sources')
    catkin_package(root, 'good', {'good.cpp': GOOD_NODE})
    catkin_package(root, 'truncated', {'cut.cpp': GOOD_NODE[:len(GOOD_NODE) // 2]})
    catkin_package(root, 'latin1', {'latin1.cpp': GOOD_NODE.replace(
        '"n"', '"n\xe9"').encode('latin-1')})
    catkin_package(root, 'deleted', {'gone.cpp': None, 'here.cpp': GOOD_NODE})
    catkin_package(root, 'nocompiler', {'n.cpp': GOOD_NODE},
                   command='/nonexistent/bin/c++')
    catkin_package(root, 'noinclude', {
        'n.cpp': '#include <acme/missing.h>\n' + GOOD_NODE})
    # about 5 MB of generated code around one real node
    filler = ''.join(
        f'static int generated_{i}(int x) {{ return x * {i} + {i % 7}; }}\n'
        for i in range(90000))
    catkin_package(root, 'huge', {'huge.cpp': GOOD_NODE + filler})
    result = _analyze(root)
    return root, result


def test_analyze_finishes_with_one_line_per_package(bad_sources):
    root, result = bad_sources
    assert result.returncode == 0
    assert_no_traceback(result)
    for name in ('good', 'truncated', 'latin1', 'deleted', 'nocompiler',
                 'noinclude', 'huge'):
        assert sum(line.startswith(f'rsia: {name}: ')
                   for line in result.stdout.splitlines()) == 1, name


def test_good_package_is_analyzed(bad_sources):
    root, _ = bad_sources
    [node] = read_summary(root, 'good')['nodes']
    assert node['publishers'][0]['label'] == 'independent'


def test_truncated_source_reports_parse_errors(bad_sources):
    root, _ = bad_sources
    summary = read_summary(root, 'truncated')
    assert any('src/cut.cpp' in d and 'parse error' in d
               for d in summary['diagnostics'])


def test_non_utf8_source_is_analyzed(bad_sources):
    root, _ = bad_sources
    [node] = read_summary(root, 'latin1')['nodes']
    assert [p['topic'] for p in node['publishers']] == ['out']


def test_stale_database_entry_is_named_and_the_rest_analyzed(bad_sources):
    root, _ = bad_sources
    summary = read_summary(root, 'deleted')
    assert any('src/gone.cpp: source file missing' in d
               for d in summary['diagnostics'])
    assert [n['id'] for n in summary['nodes']] == ['deleted/here']


def test_missing_compiler_does_not_matter(bad_sources):
    root, _ = bad_sources
    [node] = read_summary(root, 'nocompiler')['nodes']
    assert node['publishers'][0]['topic'] == 'out'


def test_unresolvable_include_gets_a_stand_in_in_model_mode(bad_sources):
    root, _ = bad_sources
    summary = read_summary(root, 'noinclude')
    assert summary['header_mode'] == 'model'
    [node] = summary['nodes']
    assert node['publishers'][0]['topic'] == 'out'
    stand_in = root / 'build' / 'noinclude' / 'rsia' / 'stubs'
    assert list(stand_in.rglob('missing.h'))
    assert not list((root / 'src').rglob('missing.h'))


def test_unresolvable_include_is_named_in_exact_mode(tmp_path):
    catkin_package(tmp_path, 'noinclude', {
        'n.cpp': '#include <acme/missing.h>\n' + GOOD_NODE})
    result = run_colcon(
        ['rsia', 'analyze', '--base-paths', str(tmp_path / 'src'),
         '--build-base', str(tmp_path / 'build'), '--header-mode', 'exact'],
        cwd=tmp_path)
    assert result.returncode == 0
    assert_no_traceback(result)
    summary = read_summary(tmp_path, 'noinclude')
    assert any("'acme/missing.h' file not found" in d
               for d in summary['diagnostics'])
    assert 'rsia: noinclude: 0 nodes' not in result.stdout


def test_five_megabyte_source_is_analyzed(bad_sources):
    root, _ = bad_sources
    assert (root / 'src/huge/src/huge.cpp').stat().st_size > 5_000_000
    [node] = read_summary(root, 'huge')['nodes']
    assert node['publishers'][0]['label'] == 'independent'


def test_missing_clang_resource_dir_gives_the_install_hint(
        tmp_path, monkeypatch):
    package = catkin_package(tmp_path, 'p', {'p.cpp': GOOD_NODE})
    monkeypatch.setattr(
        'colcon_rsia.package.analysis.find_resource_dir', lambda: None)
    outcome = runner.analyze(
        name='p', package_type='ros.catkin', path=str(package),
        build_base=str(tmp_path / 'build' / 'p'))
    assert 'apt-get install libclang-common-19-dev' in outcome.error
    assert 'RSIA_CLANG_RESOURCE_DIR' in outcome.error


def test_symlink_loops_in_the_source_tree(tmp_path):
    package = catkin_package(tmp_path, 'loopy', {'n.cpp': GOOD_NODE})
    os.symlink('..', package / 'src' / 'up')
    os.symlink(package, package / 'self')
    (package / 'scripts').mkdir()
    os.symlink('../scripts', package / 'scripts' / 'again')
    result = _analyze(tmp_path, 'loopy')
    assert result.returncode == 0, result.stderr
    assert_no_traceback(result)
    assert [n['id'] for n in read_summary(tmp_path, 'loopy')['nodes']] == \
        ['loopy/n']


# --- summaries that cannot be used -------------------------------------------

@pytest.mark.parametrize('content, message', [
    ('{"schema": "colcon-rsia/summary@1", "nod', 'corrupted summary'),
    ('{"schema": "colcon-rsia/summary@7", "nodes": []}',
     "unsupported summary schema 'colcon-rsia/summary@7'"),
    ('', 'corrupted summary'),
])
def test_unusable_summary_is_one_warning_and_hides_nothing(
        system_workspace, tmp_path, content, message):
    root = tmp_path / 'ws'
    build = root / 'build'
    for package in ('sysbot_drivers', 'sysbot_navigation'):
        source = system_workspace.build_base / package / 'rsia'
        target = build / package / 'rsia'
        target.mkdir(parents=True)
        (target / 'summary.json').write_text(
            (source / 'summary.json').read_text())
    # a killed build leaves its temp file next to an intact summary
    (build / 'sysbot_drivers' / 'rsia' / '.summary.json1234.tmp').write_text(
        '{"schema": "colcon-rsia/su')
    broken = build / 'sysbot_perception' / 'rsia'
    broken.mkdir(parents=True)
    (broken / 'summary.json').write_text(content)
    result = run_colcon(
        ['rsia', 'graph', '--base-paths', str(system_workspace.src),
         '--build-base', str(build), '--format', 'json'], cwd=root)
    assert result.returncode == 0
    assert_no_traceback(result)
    assert result.stderr.count(message) == 1
    assert 'sysbot_perception' in result.stderr
    ids = {n['id'] for n in json.loads(result.stdout)['nodes']}
    assert 'sysbot_drivers/laser_driver' in ids
    assert 'sysbot_navigation/planner' in ids


# --- launch files given on the command line ---------------------------------

@pytest.mark.parametrize('content, message', [
    ('<launch><node pkg="a" type="b" name="c"></launch>', 'launch'),
    ('<?xml version="1.0"?>\n<!DOCTYPE l [<!ENTITY a "aaaaaaaaaa">'
     '<!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">'
     '<!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">]>\n'
     '<launch><arg name="x" default="&c;"/></launch>', 'launch'),
    ('<?xml version="1.0"?>\n<!DOCTYPE l [<!ENTITY x SYSTEM '
     '"file:///etc/passwd">]>\n<launch><arg name="x" default="&x;"/>'
     '</launch>', 'launch'),
])
def test_bad_launch_file_is_one_message(system_workspace, tmp_path, content,
                                        message):
    launch = tmp_path / 'bad.launch'
    launch.write_text(content)
    result = system_workspace.colcon(
        'rsia', 'impact', '--base-paths', str(system_workspace.src),
        '--launch', str(launch), '--changed', 'x/y')
    assert result.returncode == 1
    assert_no_traceback(result)
    assert str(launch) in result.stderr or 'bad.launch' in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


# --- two builds of one workspace at once -------------------------------------

def test_two_concurrent_builds_with_the_handler(tmp_path):
    root = tmp_path / 'ws'
    first = build_workspace(FAULTS, root, extra=[
        '--packages-select', 'fault_good', 'fault_scripts'])
    assert first.returncode == 0, first.stderr
    results = []

    def build(number):
        # colcon's own 'latest' log symlink races between two runs sharing
        # a log base: give each its own, the builds share everything else
        results.append(build_workspace(FAULTS, root, extra=[
            '--packages-select', 'fault_good', 'fault_scripts'],
            log_base=f'log{number}'))
    threads = [threading.Thread(target=build, args=(n,)) for n in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert [r.returncode for r in results] == [0, 0], \
        [r.stderr for r in results]
    for result in results:
        assert_no_traceback(result)
    summary = first.summary('fault_good')
    assert summary['nodes'][0]['id'] == 'fault_good/talker'
    leftovers = subprocess.run(
        ['find', str(root / 'build'), '-name', '*.tmp'],
        capture_output=True, text=True).stdout
    assert leftovers == ''
