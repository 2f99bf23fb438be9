# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The analysis of the ROS 1 test workspace against hand-written files."""

import json
from pathlib import Path
import re

from conftest import run_colcon
from conftest import WORKSPACES
from projection import project_nodes
import pytest
import yaml

EXPECTED = sorted((WORKSPACES / 'ros1' / 'expected').glob('*.yaml'))
# the calls a publish site may name, by the API that publishes there
PUBLISH_WORDS = re.compile(
    r'publish|sendTransform|unlockAndPublish|update|broadcast')


def _expected(path):
    with open(path) as h:
        return yaml.safe_load(h)


@pytest.mark.parametrize('path', EXPECTED, ids=[p.stem for p in EXPECTED])
def test_package_matches_expected_file(ros1_workspace, path):
    expected = _expected(path)
    summary = ros1_workspace.summary(expected['package'])
    want = project_nodes(expected.get('nodes') or [])
    got = project_nodes(summary['nodes'])
    assert sorted(got) == sorted(want), 'node ids differ'
    for node_id in sorted(want):
        for section in ('publishers', 'subscribers', 'timers', 'services',
                        'actions'):
            assert got[node_id][section] == want[node_id][section], \
                f'{node_id} {section}'
        assert got[node_id]['kind'] == want[node_id]['kind'], node_id


def test_expected_files_cover_every_analysed_package(ros1_workspace):
    analysed = {
        p.parent.parent.name
        for p in ros1_workspace.build_base.glob('*/rsia/summary.json')}
    assert analysed == {_expected(p)['package'] for p in EXPECTED}


def _source_line(package_path, location):
    file, _, line = location.rpartition(':')
    lines = (Path(package_path) / file).read_text().splitlines()
    return lines[int(line) - 1]


def test_every_label_has_evidence_pointing_at_code(ros1_workspace):
    checked = 0
    for path in EXPECTED:
        summary = ros1_workspace.summary(_expected(path)['package'])
        for node in summary['nodes']:
            for publisher in node['publishers']:
                assert publisher['evidence'], publisher
                for site in publisher['publish_sites']:
                    text = _source_line(summary['path'], site)
                    assert PUBLISH_WORDS.search(text), (site, text)
                    checked += 1
                kinds = {e['kind'] for e in publisher['evidence']}
                pattern = publisher['pattern']
                if pattern in ('timer', 'mixed'):
                    assert 'timer' in kinds, publisher
                if pattern in ('rate_loop', 'mixed'):
                    assert 'rate_loop' in kinds, publisher
                    for e in publisher['evidence']:
                        if e['kind'] == 'rate_loop':
                            text = _source_line(summary['path'], e['location'])
                            assert re.search(r'\b(while|for|do)\b', text), text
                if pattern == 'no_subscribers':
                    assert 'no_subscribers' in kinds
                if publisher['label'] == 'dependent' and \
                        publisher['publish_sites']:
                    assert 'path' in kinds, publisher
    assert checked > 0


@pytest.fixture(scope='module')
def unbuilt_model_summaries(tmp_path_factory):
    """The ros1 workspace analysed without a build, with the model headers."""
    root = tmp_path_factory.mktemp('ros1_unbuilt')
    result = run_colcon(
        ['rsia', 'analyze', '--base-paths', str(WORKSPACES / 'ros1' / 'src'),
         '--header-mode', 'model'], cwd=root, check=True)
    assert 'Traceback' not in result.stdout + result.stderr
    return root / 'build'


@pytest.mark.parametrize('path', EXPECTED, ids=[p.stem for p in EXPECTED])
def test_unbuilt_workspace_in_model_mode_matches_expected_file(
        unbuilt_model_summaries, path):
    expected = _expected(path)
    summary = json.loads((
        unbuilt_model_summaries / expected['package'] / 'rsia' /
        'summary.json').read_text())
    assert summary['header_mode'] == 'model'
    assert project_nodes(summary['nodes']) == \
        project_nodes(expected.get('nodes') or [])
