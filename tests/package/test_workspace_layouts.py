# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Every package is analysed whatever the workspace layout users have.

colcon's default base path is the workspace root, which also holds the
build base: the stand-ins written there must not be mistaken for sources
(they once failed every package), and a package's headers must be found
wherever the package lies.
"""

import json
import os
from pathlib import Path
import shutil

from conftest import run_colcon
from conftest import WORKSPACES
import pytest

# the executables of test_workspaces/fig2 (read from its CMakeLists.txt)
FIG2_NODES = {
    'cob_sensors/laser_scanner', 'cob_sensors/camera',
    'cob_processing/relay', 'cob_processing/merger',
    'cob_processing/throttle', 'cob_processing/rate_loop_node',
    'cob_processing/sink', 'cob_processing/scan_filter'}
FIG2_PACKAGES = {'cob_bringup', 'cob_processing', 'cob_sensors'}


def _workspace(tmp_path):
    root = tmp_path / 'ws'
    shutil.copytree(WORKSPACES / 'fig2' / 'src', root / 'src')
    return root


def _node_ids(build_base):
    ids = set()
    for package in FIG2_PACKAGES:
        path = build_base / package / 'rsia' / 'summary.json'
        summary = json.loads(path.read_text())
        ids |= {node['id'] for node in summary['nodes']}
        for unit in summary['coverage']['units']:
            assert unit['package_errors'] == 0, (package, unit)
    return ids


def _assert_all_analyzed(result, build_base, root):
    output = result.stdout + result.stderr
    assert result.returncode == 0, output
    assert 'analysis failed' not in output, output
    assert 'internal error' not in output, output
    assert f'analysed {len(FIG2_PACKAGES)} of {len(FIG2_PACKAGES)} ' \
        'packages' in output, output
    assert _node_ids(build_base) == FIG2_NODES
    # stand-ins are build output: nothing written among the sources
    written = [p for p in (root / 'src').rglob('*') if 'rsia' in p.parts]
    assert written == []


@pytest.mark.parametrize('base_paths', [[], ['.'], ['src']],
                         ids=['default', 'dot', 'src'])
def test_unbuilt_analysis_from_the_workspace_root(tmp_path, base_paths):
    root = _workspace(tmp_path)
    args = ['rsia', 'analyze'] + (['--base-paths'] + base_paths
                                  if base_paths else [])
    result = run_colcon(args, cwd=root)
    _assert_all_analyzed(result, root / 'build', root)


def test_the_build_base_is_not_crawled_for_packages(tmp_path):
    # a build base of another name at the root, as colcon build marks its
    # own: the next command's package discovery does not enter it (a
    # package.xml left there would otherwise be a package of the workspace)
    root = _workspace(tmp_path)
    result = run_colcon(
        ['rsia', 'analyze', '--build-base', 'build_rsia'], cwd=root)
    _assert_all_analyzed(result, root / 'build_rsia', root)
    stray = root / 'build_rsia' / 'stray'
    stray.mkdir()
    (stray / 'package.xml').write_text(
        (root / 'src' / 'cob_sensors' / 'package.xml').read_text().replace(
            'cob_sensors', 'stray_copy'))
    listed = run_colcon(['list', '--names-only'], cwd=root, check=True)
    assert set(listed.stdout.split()) == FIG2_PACKAGES


def test_build_base_outside_the_workspace(tmp_path):
    root = _workspace(tmp_path)
    elsewhere = tmp_path / 'elsewhere' / 'build'
    result = run_colcon(
        ['rsia', 'analyze', '--build-base', str(elsewhere)], cwd=root)
    _assert_all_analyzed(result, elsewhere, root)
    assert not (root / 'build').exists()


def test_symlinked_workspace(tmp_path):
    root = _workspace(tmp_path)
    link = tmp_path / 'link'
    os.symlink(root, link)
    result = run_colcon(['rsia', 'analyze'], cwd=link)
    _assert_all_analyzed(result, Path(link) / 'build', root)


def test_coverage_of_the_analyzed_workspace(tmp_path):
    root = _workspace(tmp_path)
    run_colcon(['rsia', 'analyze'], cwd=root, check=True)
    result = run_colcon(['rsia', 'coverage', '--format', 'json'], cwd=root,
                        check=True)
    report = json.loads(result.stdout)
    assert report['schema'] == 'colcon-rsia/coverage@1'
    by_name = {p['package']: p for p in report['packages']}
    assert set(by_name) == FIG2_PACKAGES
    # cob_bringup holds launch files only; the two others are C++
    assert by_name['cob_bringup']['units'] == 0
    total = report['total']
    assert total['failed'] == 0 and total['units_with_errors'] == 0
    # every publisher/subscription call of the code is a fact of a node:
    # laser_scanner, camera: 1 advertise each; relay, throttle,
    # rate_loop_node, scan_filter: 1 advertise + 1 subscribe; merger:
    # 1 advertise + 2 subscribe; sink: 1 subscribe
    calls = total['call_sites']
    assert calls['publisher'] == {
        'sites': 7, 'in_nodes': 7, 'in_units_only': 0, 'from_tokens': 0}
    assert calls['subscriber'] == {
        'sites': 7, 'in_nodes': 7, 'in_units_only': 0, 'from_tokens': 0}
    assert total['percent'] == 100.0
    # a share above 100 % is no threshold (issue 40): a usage error
    above = run_colcon(
        ['rsia', 'coverage', '--fail-under', '100.5'], cwd=root)
    assert above.returncode == 1, above.stdout + above.stderr
    assert run_colcon(['rsia', 'coverage', '--fail-under', '100'],
                      cwd=root).returncode == 0


def test_coverage_names_the_packages_whose_analysis_failed(tmp_path):
    root = _workspace(tmp_path)
    # a compile database that is not JSON: cob_sensors cannot be analysed
    database = root / 'build' / 'cob_sensors' / 'compile_commands.json'
    database.parent.mkdir(parents=True)
    database.write_text('{ not json')
    analyzed = run_colcon(['rsia', 'analyze'], cwd=root)
    # a package failed: analyze says so in its exit code (issue 40)
    assert analyzed.returncode == 1, analyzed.stdout + analyzed.stderr
    assert '1 packages failed' in analyzed.stdout
    result = run_colcon(['rsia', 'coverage', '--format', 'json'], cwd=root,
                        check=True)
    by_name = {p['package']: p for p in json.loads(result.stdout)['packages']}
    assert by_name['cob_sensors']['status'] == 'failed'
    assert 'compile_commands.json' in by_name['cob_sensors']['error']
    assert by_name['cob_processing']['status'] == 'analysed'
    # a failed package fails the check, whatever the share
    assert run_colcon(['rsia', 'coverage', '--fail-under', '0'],
                      cwd=root).returncode == 2
    # once analysed again, the failure is gone
    database.unlink()
    run_colcon(['rsia', 'analyze'], cwd=root, check=True)
    result = run_colcon(['rsia', 'coverage', '--format', 'json'], cwd=root,
                        check=True)
    by_name = {p['package']: p for p in json.loads(result.stdout)['packages']}
    assert by_name['cob_sensors']['status'] == 'analysed'
