# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The CI recipe of docs/ci.md does what it says, on a pull request.

The workflow's own `colcon rsia` steps run, as written, in a git
repository holding the system test workspace, on a branch that changes
the laser driver. Expectations from test_workspaces/system/expected.yaml:
the laser's rate reaches the scan filter and the planner.
"""

import os
from pathlib import Path
import shutil
import subprocess
import sys

from conftest import REPO
from conftest import WORKSPACES
import pytest
import yaml

WORKFLOW = REPO / 'docs' / 'ci' / 'rate-impact.yml'
GIT_ENV = {
    'GIT_AUTHOR_NAME': 'test', 'GIT_AUTHOR_EMAIL': 'test@example.com',
    'GIT_COMMITTER_NAME': 'test', 'GIT_COMMITTER_EMAIL': 'test@example.com'}


def _git(repo, *args):
    subprocess.run(['git', *args], cwd=repo, check=True, capture_output=True,
                   env=dict(os.environ, **GIT_ENV))


@pytest.fixture(scope='module')
def pull_request(tmp_path_factory):
    """A clone whose branch changes the laser driver, and origin/main."""
    repo = tmp_path_factory.mktemp('pr') / 'repo'
    shutil.copytree(WORKSPACES / 'system' / 'src', repo / 'src')
    _git(repo, 'init', '-q', '-b', 'main')
    _git(repo, 'add', '-A')
    _git(repo, 'commit', '-q', '-m', 'base')
    _git(repo, 'update-ref', 'refs/remotes/origin/main', 'HEAD')
    _git(repo, 'checkout', '-q', '-b', 'feature')
    driver = repo / 'src' / 'sysbot_drivers' / 'src' / 'laser_driver.cpp'
    driver.write_text(driver.read_text() + '// a change under review\n')
    _git(repo, 'commit', '-q', '-am', 'change the laser driver')
    return repo


def _steps():
    workflow = yaml.safe_load(WORKFLOW.read_text())
    [job] = workflow['jobs'].values()
    return workflow, job['steps']


def _run_step(step, repo, env):
    return subprocess.run(
        ['bash', '-e', '-c', step['run']], cwd=repo, env=env,
        capture_output=True, text=True, timeout=900)


def test_the_workflow_steps_on_a_pull_request(pull_request, tmp_path):
    workflow, steps = _steps()
    # YAML 1.1 reads the key `on` as true
    assert 'pull_request' in workflow[True]
    summary = tmp_path / 'step_summary.md'
    env = dict(
        os.environ, **workflow['env'],
        GITHUB_BASE_REF='main', GITHUB_STEP_SUMMARY=str(summary),
        COLCON_HOME=str(tmp_path / 'colcon_home'),
        # the workflow puts the venv's colcon on PATH; here it is the tests'
        PATH=f'{Path(sys.executable).parent}{os.pathsep}{os.environ["PATH"]}')
    env['RSIA_FAIL_ON'] = 'sysbot_navigation/planner'
    ran = {}
    for step in steps:
        if 'colcon rsia' not in step.get('run', ''):
            continue
        result = _run_step(step, pull_request, env)
        ran[step['name']] = (step, result)
        assert 'Traceback' not in result.stderr, result.stderr
    analyze, impact, report = ran.values()
    assert analyze[1].returncode == 0, analyze[1].stdout + analyze[1].stderr
    # the gate: the planner follows the laser's rate
    assert impact[1].returncode == 2, impact[1].stdout + impact[1].stderr
    assert 'rate impact: 2 nodes' in impact[1].stdout
    assert '  sysbot_navigation/planner\n  sysbot_perception/scan_filter\n' \
        in impact[1].stdout
    assert 'changed sysbot_drivers/laser_driver' in impact[1].stderr
    assert 'sysbot_navigation/planner' in impact[1].stderr
    # the report still runs after the failed gate, and fills the summary
    assert report[0].get('if') and 'success' not in report[0]['if']
    assert report[1].returncode == 0, report[1].stderr
    assert (pull_request / 'rsia-report' / 'index.html').is_file()
    text = summary.read_text()
    assert 'colcon-rsia: rate impact' in text
    assert '`sysbot_navigation/planner`' in text


def test_the_report_is_uploaded_from_where_it_is_written():
    _, steps = _steps()
    [upload] = [s for s in steps
                if s.get('uses', '').startswith('actions/upload-artifact')]
    [report] = [s for s in steps if 'colcon rsia report' in s.get('run', '')]
    assert f"--output {upload['with']['path']}" in report['run']
    assert upload.get('if') == report.get('if')


SHARDS_WORKFLOW = REPO / 'docs' / 'ci' / 'rate-impact-shards.yml'


def test_the_sharded_workflow_on_a_pull_request(pull_request, tmp_path):
    """The shard jobs one after another in the same checkout, then the last.

    The artifacts are the shards' tar files, put where the download step
    puts them (`shards/<artifact name>/`); each shard's `build` is removed
    before the next, as a fresh runner has none.
    """
    # a fresh clone: no build base of another test
    repo = tmp_path / 'repo'
    shutil.copytree(pull_request, repo, ignore=shutil.ignore_patterns(
        'build', 'install', 'log', 'rsia-report'))
    workflow = yaml.safe_load(SHARDS_WORKFLOW.read_text())
    analyze, rate_impact = workflow['jobs']['analyse'], \
        workflow['jobs']['rate-impact']
    assert rate_impact['needs'] == 'analyse'
    env = dict(
        os.environ, **workflow['env'],
        GITHUB_BASE_REF='main',
        GITHUB_STEP_SUMMARY=str(tmp_path / 'step_summary.md'),
        COLCON_HOME=str(tmp_path / 'colcon_home'),
        PATH=f'{Path(sys.executable).parent}{os.pathsep}{os.environ["PATH"]}')
    env['RSIA_FAIL_ON'] = 'sysbot_navigation/planner'
    # this workspace's shards: sysbot_perception in both
    shards = {'sensing': 'sysbot_drivers sysbot_perception',
              'navigation': 'sysbot_navigation sysbot_perception'}
    [upload] = [s for s in analyze['steps']
                if s.get('uses', '').startswith('actions/upload-artifact')]
    artifact = upload['with']['path']
    for name, packages in shards.items():
        for step in analyze['steps']:
            if 'run' not in step or 'Install' in step['name']:
                continue
            step_env = dict(env, **{
                k: v.replace('${{ matrix.shard.packages }}', packages)
                for k, v in step.get('env', {}).items()})
            result = _run_step(step, repo, step_env)
            assert result.returncode == 0, (step['name'], result.stdout,
                                            result.stderr)
        shard = repo / 'shards' / f'rsia-shard-{name}'
        shard.mkdir(parents=True)
        shutil.move(str(repo / artifact), str(shard / artifact))
        shutil.rmtree(repo / 'build')
    ran = {}
    for step in rate_impact['steps']:
        if 'colcon rsia' in step.get('run', ''):
            ran[step['name']] = _run_step(step, repo, env)
    merge, impact, report = ran.values()
    assert merge.returncode == 0, merge.stdout + merge.stderr
    assert 'rsia: merged 3 packages' in merge.stdout
    assert impact.returncode == 2, impact.stdout + impact.stderr
    assert '  sysbot_navigation/planner\n  sysbot_perception/scan_filter\n' \
        in impact.stdout
    assert report.returncode == 0, report.stderr
    # only the analysis results travelled: no fact cache, no stand-ins
    merged = repo / 'build'
    files = sorted(str(p.relative_to(merged)) for p in merged.rglob('*')
                   if p.is_file())
    # (the marker merge puts in the build base it makes, as colcon build)
    assert files.pop(0) == 'COLCON_IGNORE'
    assert [f for f in files if f.endswith('/rsia/summary.json')] == [
        f'{package}/rsia/summary.json' for package in (
            'sysbot_drivers', 'sysbot_navigation', 'sysbot_perception')]
    assert all(f.split('/')[1:] in (['rsia', 'summary.json'],
                                    ['rsia', 'wrappers.json'])
               for f in files), files
