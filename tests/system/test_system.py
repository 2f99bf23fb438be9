# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""End to end: build the system workspace with rsia+, then graph/impact."""


from conftest import build_workspace
from conftest import WORKSPACES
from helpers import colcon_json
import pytest
import yaml

EXPECTED = yaml.safe_load(
    (WORKSPACES / 'system' / 'expected.yaml').read_text())


def test_build_prints_one_line_per_package_and_a_total(system_workspace):
    out = system_workspace.stdout
    for package in ('sysbot_drivers', 'sysbot_perception',
                    'sysbot_navigation'):
        assert f'rsia: {package}: ' in out
    assert 'rsia: analysed 3 of 3 packages (8 nodes)' in out


def test_graph_json_matches_hand_derived_labels(system_workspace):
    graph = colcon_json(system_workspace, 'graph')
    assert graph['schema'] == 'colcon-rsia/graph@1'
    got = {}
    for node in graph['nodes']:
        got[node['id']] = {
            'publishes': {p['resolved']: p['label']
                          for p in node['publishers']},
            'subscribes': sorted(s['resolved'] for s in node['subscribers']),
        }
    want = {node_id: {'publishes': dict(v['publishes']),
                      'subscribes': sorted(v['subscribes'])}
            for node_id, v in EXPECTED['nodes'].items()}
    assert got == want
    topics = {t['name']: t for t in graph['topics']}
    assert topics['/plan']['subscribers'] == [
        'sysbot_navigation/controller', 'sysbot_navigation/system_monitor']


@pytest.mark.parametrize(
    'case', EXPECTED['impact'],
    ids=['+'.join(c.split('/')[1] for c in case['changed'])
         for case in EXPECTED['impact']])
def test_impact_matches_hand_derived_sets(system_workspace, case):
    result = colcon_json(system_workspace, 'impact', '--changed', *case['changed'])
    # every dependent publisher here is driven by each input of its node
    # (one input each): the trigger model gives the paper's sets
    assert result == {
        'schema': 'colcon-rsia/impact@1',
        'changed': sorted(case['changed']),
        'model': 'paper',
        'rate_impact': case['rate_impact'],
        'traditional_impact': case['traditional_impact'],
        'paper_impact': case['rate_impact'],
        'trigger_impact': case['rate_impact'],
        'not_triggered': [],
    }


def test_impact_text_shows_both_sizes(system_workspace):
    result = system_workspace.colcon(
        'rsia', 'impact', '--base-paths', str(system_workspace.src),
        '--changed', 'sysbot_drivers/laser_driver', '--traditional',
        check=True)
    assert 'rate impact: 2 nodes; traditional: 5' in result.stdout
    assert '  sysbot_perception/scan_filter' in result.stdout


def test_impact_all_matches_hand_derived_sizes(system_workspace):
    result = colcon_json(system_workspace, 'impact', '--all')
    got = {row['id']: {'rate': row['rate_impact'],
                       'traditional': row['traditional_impact']}
           for row in result['nodes']}
    assert got == EXPECTED['all']
    rate = sum(v['rate'] for v in EXPECTED['all'].values())
    traditional = sum(v['traditional'] for v in EXPECTED['all'].values())
    assert result['ratio'] == round(rate / traditional, 3)
    assert result['average_rate_impact'] == round(
        rate / len(EXPECTED['all']), 3)


def test_unknown_node_is_an_error_naming_close_ones(system_workspace):
    result = system_workspace.colcon(
        'rsia', 'impact', '--base-paths', str(system_workspace.src),
        '--changed', 'sysbot_drivers/laser_drivr')
    assert result.returncode != 0
    assert "unknown node 'sysbot_drivers/laser_drivr'" in result.stderr
    assert 'sysbot_drivers/laser_driver' in result.stderr
    assert 'Traceback' not in result.stderr


def test_graph_dot_draws_independent_edges_dashed(system_workspace):
    result = system_workspace.colcon(
        'rsia', 'graph', '--base-paths', str(system_workspace.src),
        '--format', 'dot', check=True)
    dot = result.stdout
    assert dot.startswith('digraph rsia {')
    assert '"node:sysbot_navigation/planner" -> "topic:/plan" ' \
        '[style=dashed, label="independent"];' in dot
    # a dependent edge names the topics that trigger it
    assert '"node:sysbot_navigation/controller" -> "topic:/cmd_vel" ' \
        '[label="triggered by /plan"];' in dot


def test_analyze_subverb_reproduces_the_handler_summary(system_workspace):
    before = system_workspace.summary('sysbot_navigation')
    result = system_workspace.colcon(
        'rsia', 'analyze', '--base-paths', str(system_workspace.src),
        '--packages-select', 'sysbot_navigation', check=True)
    assert 'rsia: sysbot_navigation: 3 nodes' in result.stdout
    after = system_workspace.summary('sysbot_navigation')
    for summary in (before, after):
        # how long each took, and where the time went
        summary.pop('seconds')
        summary.pop('phases')
    assert before == after


def test_build_without_compile_commands_warns_and_stays_green(
        tmp_path_factory):
    workspace = build_workspace(
        WORKSPACES / 'system' / 'src', tmp_path_factory.mktemp('no_db'),
        compile_commands=False,
        extra=['--packages-select', 'sysbot_perception'])
    assert workspace.returncode == 0, workspace.stderr
    out = workspace.stdout
    assert out.count('rsia: sysbot_perception: no compile_commands.json') \
        == 1
    assert '--cmake-args -DCMAKE_EXPORT_COMPILE_COMMANDS=ON' in out
    assert 'Traceback' not in out + workspace.stderr
    assert not (workspace.build_base / 'sysbot_perception' / 'rsia' /
                'summary.json').exists()


def test_impact_all_under_both_models(system_workspace):
    result = colcon_json(system_workspace, 'impact', '--all', '--model', 'trigger')
    # one input per dependent publisher (scan_filter: /scan, obstacle_
    # detector: /image, controller: /plan, base_driver: /cmd_vel): the
    # trigger model gives the paper's sizes
    got = {row['id']: {'rate': row['paper_impact'],
                       'traditional': row['traditional_impact']}
           for row in result['nodes']}
    assert got == EXPECTED['all']
    assert all(row['trigger_impact'] == row['paper_impact']
               for row in result['nodes'])
    assert result['trigger_ratio'] == result['paper_ratio']


def test_rates(system_workspace):
    result = colcon_json(system_workspace, 'rates')
    got = {t['name']: (t['hz'], t['source']) for t in result['topics']}
    # by hand: laser_driver Rate(10.0), camera_driver timer 0.05 s,
    # base_driver Rate(50.0), scan_filter stats timer 1 s, planner timer
    # 0.2 s; the dependent publishers follow their one input
    assert got == {
        '/scan': (10, 'Rate loop'), '/image': (20, 'timer'),
        '/odom': (50, 'Rate loop'), '/filter_stats': (1, 'timer'),
        '/plan': (5, 'timer'), '/scan_filtered': (10, 'follows /scan'),
        '/obstacles': (20, 'follows /image'),
        '/cmd_vel': (5, 'follows /plan'),
        '/base_status': (5, 'follows /cmd_vel')}
