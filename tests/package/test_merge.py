# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""`colcon rsia merge`: build bases of CI shards into one, and its refusals.

The shards here are written by hand (the generated system of
synthetic_system.py, three packages of eight nodes: pkg_000 to pkg_002);
tests/package/test_shards.py merges shards the analysis made. Every command runs
through the `colcon` script from a directory holding no package, where the
queries read every summary of the build base.
"""

import json
from pathlib import Path

from colcon_rsia import __version__
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.store import write_summary
from conftest import run_colcon
import pytest
from synthetic_system import synthetic_summaries

SUMMARY = Path('rsia') / 'summary.json'
WRAPPERS = Path('rsia') / 'wrappers.json'
FAILURE = Path('rsia') / 'failure.json'


def _summaries(root):
    """The generated system, its packages' sources in `root`/src."""
    summaries = {}
    for summary in synthetic_summaries(24):
        summary.path = str(root / 'src' / summary.package)
        (root / 'src' / summary.package).mkdir(parents=True, exist_ok=True)
        summaries[summary.package] = summary
    assert sorted(summaries) == ['pkg_000', 'pkg_001', 'pkg_002']
    return summaries


def _write(base, *summaries):
    for summary in summaries:
        write_summary(str(base / summary.package), summary)


def _rsia(root, *args):
    result = run_colcon(['rsia', *args], cwd=root, timeout=120)
    assert 'Traceback' not in result.stderr, result.stderr
    return result


def _merge_lines(result):
    return [line for line in result.stderr.splitlines()
            if line.startswith('rsia: merge: ')]


def _json(result):
    assert result.returncode == 0, result.stdout + result.stderr
    return json.loads(result.stdout)


def test_shards_merged_answer_as_the_whole(tmp_path):
    summaries = _summaries(tmp_path)
    _write(tmp_path / 'whole', *summaries.values())
    _write(tmp_path / 'shard1', summaries['pkg_000'], summaries['pkg_001'])
    # pkg_001 in both shards: the same analysis, which took longer here
    summaries['pkg_001'].seconds = 9.5
    _write(tmp_path / 'shard2', summaries['pkg_001'], summaries['pkg_002'])

    result = _rsia(tmp_path, 'merge', '--from', 'shard1', 'shard2')
    assert result.returncode == 0, result.stdout + result.stderr
    assert _merge_lines(result) == []
    assert result.stdout.strip() == (
        f"rsia: merged 3 packages into '{tmp_path / 'build'}' (1 of them "
        'analysed the same in several build bases)')
    # each file as its shard wrote it; pkg_001 from the first shard named
    for package, shard in (('pkg_000', 'shard1'), ('pkg_001', 'shard1'),
                           ('pkg_002', 'shard2')):
        assert (tmp_path / 'build' / package / SUMMARY).read_bytes() == \
            (tmp_path / shard / package / SUMMARY).read_bytes()

    for query in (['impact', '--all', '--format', 'json'],
                  ['graph', '--format', 'json'],
                  ['impact', '--changed', 'pkg_000/node_0002',
                   '--format', 'json']):
        merged = _json(_rsia(tmp_path, *query))
        assert merged == _json(_rsia(tmp_path, *query, '--build-base',
                                     'whole')), query
    graph = _json(_rsia(tmp_path, 'graph', '--format', 'json'))
    assert len(graph['nodes']) == 24


def test_different_analyses_of_a_package_are_a_conflict(tmp_path):
    summaries = _summaries(tmp_path)
    _write(tmp_path / 'shard1', summaries['pkg_000'], summaries['pkg_001'])
    summaries['pkg_001'].nodes.pop()
    _write(tmp_path / 'shard2', summaries['pkg_001'], summaries['pkg_002'])

    result = _rsia(tmp_path, 'merge', '--from', 'shard1', 'shard2')
    assert result.returncode == 1
    [conflict] = _merge_lines(result)
    assert conflict.startswith('rsia: merge: pkg_001: the build bases ')
    assert f"'{tmp_path / 'shard1'}' and '{tmp_path / 'shard2'}'" in conflict
    assert '(summary.json differs in nodes)' in conflict
    assert 'not merged' in conflict
    assert 'rsia: merged 2 packages' in result.stdout
    # the packages merged; the build base marked as colcon build marks its
    # own (COLCON_IGNORE: no package discovery crawls it)
    assert sorted(p.name for p in (tmp_path / 'build').iterdir()) == \
        ['COLCON_IGNORE', 'pkg_000', 'pkg_002']


def _valid(name, root):
    (root / 'src' / name).mkdir(parents=True, exist_ok=True)
    return PackageSummary(package=name, path=str(root / 'src' / name),
                          tool_version=__version__)


def test_each_unreadable_file_is_one_message_and_the_rest_is_merged(
        tmp_path):
    shard = tmp_path / 'shard'
    _write(shard, *(_valid(n, tmp_path) for n in ('a', 'b', 'c', 'd')))
    (shard / 'a' / SUMMARY).write_text('{"schema": "colcon-rsia/sum')
    newer = json.loads((shard / 'b' / SUMMARY).read_text())
    newer['schema'] = 'colcon-rsia/summary@2'
    newer['a field of the next version'] = [1, 2]
    (shard / 'b' / SUMMARY).write_text(json.dumps(newer))
    (shard / 'c' / WRAPPERS).write_text(json.dumps(
        {'schema': 'colcon-rsia/wrappers@1', 'path': '/x',
         'wrappers': [{'usr': 'c:@F@f', 'name': 'f'}]}))  # no arity
    # a package whose only analysis failed, and one with wrappers only
    (shard / 'e' / 'rsia').mkdir(parents=True)
    (shard / 'e' / FAILURE).write_text(json.dumps(
        {'package': 'e', 'error': 'no compile_commands.json'}))
    (shard / 'f' / 'rsia').mkdir(parents=True)
    (shard / 'f' / WRAPPERS).write_text(json.dumps(
        {'schema': 'colcon-rsia/wrappers@1', 'path': '/x', 'wrappers': []}))
    # a build directory without analysis results is no package result
    (shard / 'g' / 'CMakeFiles').mkdir(parents=True)
    newer_text = (shard / 'b' / SUMMARY).read_bytes()

    result = _rsia(tmp_path, 'merge', '--from', 'shard', 'no_such_shard')
    assert result.returncode == 1
    lines = _merge_lines(result)
    assert len(lines) == 5, result.stderr
    a, b, c, f, missing = lines
    assert a.startswith(f"rsia: merge: a: '{shard / 'a' / SUMMARY}' is "
                        'corrupt (')
    assert b.startswith(f"rsia: merge: b: '{shard / 'b' / SUMMARY}' has the "
                        "schema 'colcon-rsia/summary@2', this version of "
                        "colcon-rsia reads 'colcon-rsia/summary@1'")
    assert 'the file is left as it is' in b
    assert c.startswith(f"rsia: merge: c: '{shard / 'c' / WRAPPERS}' is "
                        'corrupt (') and 'arity' in c
    assert f.startswith('rsia: merge: f: ') and \
        'wrappers.json but no summary.json' in f
    assert missing == (f"rsia: merge: --from '{tmp_path / 'no_such_shard'}' "
                       'does not exist; nothing merged from it')
    assert 'rsia: 5 merge problems: the packages they name were not ' \
        'merged' in result.stderr
    assert 'rsia: merged 2 packages' in result.stdout
    build = tmp_path / 'build'
    assert sorted(p.name for p in build.iterdir()) == \
        ['COLCON_IGNORE', 'd', 'e']
    assert not (build / 'e' / SUMMARY).exists()
    assert json.loads((build / 'e' / FAILURE).read_text())['error'] == \
        'no compile_commands.json'
    # nothing lost: the summary of the next version is as it was
    assert (shard / 'b' / SUMMARY).read_bytes() == newer_text


def test_a_merged_package_replaces_what_the_target_had(tmp_path):
    build = tmp_path / 'build'
    old = _valid('x', tmp_path)
    old.diagnostics = ['the analysis before']
    _write(build, old, _valid('y', tmp_path))
    (build / 'x' / FAILURE).write_text(json.dumps(
        {'package': 'x', 'error': 'it failed once'}))
    (build / 'x' / WRAPPERS).write_text(json.dumps(
        {'schema': 'colcon-rsia/wrappers@1', 'path': old.path,
         'wrappers': []}))
    y_before = (build / 'y' / SUMMARY).read_bytes()
    _write(tmp_path / 'shard', _valid('x', tmp_path))

    result = _rsia(tmp_path, 'merge', '--from', 'shard')
    assert result.returncode == 0, result.stderr
    assert json.loads((build / 'x' / SUMMARY).read_text())[
        'diagnostics'] == []
    # the shard's analysis succeeded and offered no wrappers
    assert not (build / 'x' / FAILURE).exists()
    assert not (build / 'x' / WRAPPERS).exists()
    assert (build / 'y' / SUMMARY).read_bytes() == y_before
    # no temporary file is left beside the files written
    assert sorted(p.name for p in (build / 'x' / 'rsia').iterdir()) == \
        ['summary.json']


@pytest.mark.parametrize('sources', [['build'], ['shard', '.']])
def test_the_target_is_no_source(tmp_path, sources):
    _write(tmp_path / 'build', _valid('x', tmp_path))
    _write(tmp_path / 'shard', _valid('y', tmp_path))
    build_base = 'build' if sources == ['build'] else '.'
    result = _rsia(tmp_path, 'merge', '--from', *sources,
                   '--build-base', build_base)
    assert result.returncode == 1
    assert 'is the build base merged into (--build-base)' in \
        result.stdout + result.stderr
    assert not (tmp_path / 'y').exists()


def test_a_summary_made_elsewhere_is_noted(tmp_path):
    summary = _valid('x', tmp_path)
    summary.path = '/checkout/of/another/job/src/x'
    _write(tmp_path / 'shard', summary)
    result = _rsia(tmp_path, 'merge', '--from', 'shard')
    assert result.returncode == 0, result.stderr
    assert 'rsia: note: x: its summary was made from the sources at ' \
        "'/checkout/of/another/job/src/x', not a directory here" in \
        result.stderr
