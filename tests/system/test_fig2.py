# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The paper's Fig. 2 system, deployed by ROS 1 and ROS 2 launch files."""

import json

from colcon_rsia.render.graph import graph_to_json
from colcon_rsia.summary.store import find_summaries
from colcon_rsia.summary.store import read_summary
from colcon_rsia.system.impact import expand_changed
from colcon_rsia.system.impact import impact_all
from colcon_rsia.system.impact import impact_to_json
from colcon_rsia.system.load import load_system
from colcon_rsia.system.rates import predict_rates
from colcon_rsia.system.rates import what_if
from conftest import build_workspace
from conftest import WORKSPACES
import pytest
import yaml

FIG2 = WORKSPACES / 'fig2'
EXPECTED = yaml.safe_load((FIG2 / 'expected.yaml').read_text())
LAUNCH_FILES = EXPECTED['launch']['files']
PACKAGE = EXPECTED['launch']['package']


@pytest.fixture(scope='session')
def fig2_workspace(tmp_path_factory):
    workspace = build_workspace(FIG2 / 'src', tmp_path_factory.mktemp('fig2'))
    assert workspace.returncode == 0, workspace.stdout + workspace.stderr
    return workspace


@pytest.fixture(scope='session')
def fig2_summaries(fig2_workspace):
    return [read_summary(path) for path in
            find_summaries(str(fig2_workspace.build_base)).values()]


def _package_paths():
    return {p.name: str(p) for p in (FIG2 / 'src').iterdir()}


def _system(summaries, launch_file, args):
    words = [PACKAGE, launch_file] + [f'{k}:={v}' for k, v in args.items()]
    return load_system(summaries, launch=words,
                       package_paths=_package_paths())


def _instances(system):
    graph = graph_to_json(system)
    view = {}
    for node in graph['nodes']:
        entry = {
            'node': f"{node['package']}/{node['executable']}",
            'publishes': {p['resolved']: p['label']
                          for p in node['publishers']},
            'subscribes': sorted(s['resolved'] for s in node['subscribers']),
        }
        if node['kind'] == 'unknown':
            entry['unknown'] = True
            topics = {t['name']: t for t in graph['topics']}
            entry['publishes'] = {
                name: 'dependent' for name, t in topics.items()
                if node['id'] in t['publishers']}
            entry['subscribes'] = sorted(
                name for name, t in topics.items()
                if node['id'] in t['subscribers'])
        view[node['id']] = entry
    return view


def _expected_instances(variant=None):
    instances = {k: dict(v) for k, v in EXPECTED['instances'].items()}
    for entry in instances.values():
        entry['subscribes'] = sorted(entry['subscribes'])
        entry['publishes'] = dict(entry['publishes'])
    if variant:
        for removed in variant.get('removed', []):
            instances.pop(removed)
        for name, entry in (variant.get('instances') or {}).items():
            entry = dict(entry)
            entry['subscribes'] = sorted(entry['subscribes'])
            instances[name] = entry
    return instances


VARIANTS = [None] + EXPECTED.get('launch_args', [])


@pytest.mark.parametrize('launch_file', LAUNCH_FILES)
@pytest.mark.parametrize(
    'variant', VARIANTS,
    ids=['defaults'] + [
        ','.join(f'{k}={v}' for k, v in v['args'].items())
        for v in VARIANTS[1:]])
def test_instances_and_topics(fig2_summaries, launch_file, variant):
    args = variant['args'] if variant else {}
    system = _system(fig2_summaries, launch_file, args)
    assert _instances(system) == _expected_instances(variant)


def _impact_cases():
    cases = []
    for variant in VARIANTS:
        args = variant['args'] if variant else {}
        impacts = variant['impact'] if variant else EXPECTED['impact']
        for case in impacts:
            for launch_file in LAUNCH_FILES:
                name = '+'.join(case['changed']) + (
                    f' with {args}' if args else '')
                cases.append(pytest.param(
                    launch_file, args, case, id=f'{launch_file}:{name}'))
    return cases


@pytest.mark.parametrize('launch_file, args, case', _impact_cases())
def test_impact_sets(fig2_summaries, launch_file, args, case):
    system = _system(fig2_summaries, launch_file, args)
    result = impact_to_json(system, expand_changed(system, case['changed']))
    assert result['rate_impact'] == case['rate_impact']
    assert result['traditional_impact'] == case['traditional_impact']


def test_fig2_traditional_19_rate_aware_about_half(fig2_summaries):
    system = _system(fig2_summaries, 'robot.launch', {})
    result = impact_to_json(system, ['/sensors/laser_front'])
    assert len(result['traditional_impact']) == 19
    assert len(result['rate_impact']) <= 10


def test_cli_launch_pkg_file_with_arguments(fig2_workspace):
    result = fig2_workspace.colcon(
        'rsia', 'impact', '--base-paths', str(fig2_workspace.src),
        '--launch', PACKAGE, 'robot.launch', 'use_rviz:=false',
        '--changed', '/sensors/laser_front', '--format', 'json', check=True)
    data = json.loads(result.stdout)
    assert data['changed'] == ['/sensors/laser_front']
    assert '/ui/rviz' not in data['traditional_impact']
    graph = fig2_workspace.colcon(
        'rsia', 'graph', '--base-paths', str(fig2_workspace.src),
        '--launch', PACKAGE, 'robot.launch', '--format', 'json', check=True)
    nodes = {n['id']: n for n in json.loads(graph.stdout)['nodes']}
    assert nodes['/ui/rviz']['kind'] == 'unknown'
    assert nodes['/sensors/laser_front']['package'] == 'cob_sensors'
    assert nodes['/sensors/laser_front']['executable'] == 'laser_scanner'
    assert 'not analysed' in graph.stderr


def test_cli_launch_errors_are_one_message(fig2_workspace):
    result = fig2_workspace.colcon(
        'rsia', 'graph', '--base-paths', str(fig2_workspace.src),
        '--launch', PACKAGE, 'missing.launch')
    assert result.returncode != 0
    assert "no launch file 'missing.launch' in package 'cob_bringup'" in \
        result.stderr
    assert 'Traceback' not in result.stderr


# Predicted rates (use_rviz:=false: the unknown rviz would make the topics it
# re-publishes unknown), by hand from the code: laser_scanner 10 Hz Rate
# loop, camera 15 Hz timer (1/15 s), throttle 5 Hz timer (0.2 s),
# rate_loop_node 20 Hz Rate loop; relay and scan_filter follow their input;
# both merger callbacks publish: the sum of its two inputs.
FIG2_RATES = {
    '/sensors/scan_front': (10, 'Rate loop'),
    '/sensors/scan_rear': (10, 'Rate loop'),
    '/sensors/camera/image': (15, 'timer'),
    '/sensors/scan_front_filtered': (10, 'follows /sensors/scan_front'),
    '/sensors/rear/filtered': (10, 'follows /sensors/scan_rear'),
    '/navigation/scan_unified': (20, 'sum of /sensors/scan_front_filtered, '
                                     '/sensors/rear/filtered'),
    '/navigation/pose': (20, 'Rate loop'),
    '/navigation/costmap': (5, 'timer'),
    '/perception/people': (15, 'follows /sensors/camera/image'),
    '/perception/tracks': (5, 'timer'),
    '/navigation/plan': (10, 'sum of /navigation/costmap, /perception/tracks'),
    '/navigation/cmd_vel_raw': (10, 'follows /navigation/plan'),
    '/base/cmd_vel': (30, 'sum of /navigation/cmd_vel_raw, '
                          '/navigation/scan_unified'),
    '/base/odom': (20, 'Rate loop'),
    '/base/odom_slow': (5, 'timer'),
    '/tf': (5, 'timer'),
    '/manipulation/arm_goal': (25, 'sum of /navigation/pose, '
                                   '/perception/tracks'),
    '/manipulation/joint_states': (20, 'Rate loop'),
    '/joint_states': (20, 'follows /manipulation/joint_states'),
    '/ui/image_web': (15, 'follows /sensors/camera/image'),
}


def test_predicted_rates(fig2_summaries):
    system = _system(fig2_summaries, 'robot.launch', {'use_rviz': 'false'})
    rates = predict_rates(system)
    assert {name: (rate.hz, rate.source) for name, rate in rates.items()} \
        == FIG2_RATES
    # the unknown rviz re-publishes /navigation/scan_unified: never a guess
    system = _system(fig2_summaries, 'robot.launch', {})
    assert predict_rates(system)['/navigation/scan_unified'].hz is None


def test_what_if_stops_at_independent_edges(fig2_summaries):
    system = _system(fig2_summaries, 'robot.launch', {'use_rviz': 'false'})
    changes, kept = what_if(system, set_rates={'/sensors/scan_front': 20})
    assert [(c['topic'], c['from'], c['to']) for c in changes] == [
        ('/base/cmd_vel', 30, 40), ('/navigation/scan_unified', 20, 30),
        ('/sensors/scan_front', 10, 20),
        ('/sensors/scan_front_filtered', 10, 20)]
    assert [(k['topic'], k['hz'], k['edge']) for k in kept] == [
        ('/base/odom', 20, '/base/base_driver -> /base/odom (independent)'),
        ('/navigation/costmap', 5,
         '/navigation/costmap -> /navigation/costmap (independent)'),
        ('/navigation/pose', 20,
         '/navigation/localization -> /navigation/pose (independent)')]


@pytest.mark.parametrize('launch_file', LAUNCH_FILES)
def test_trigger_model_is_never_larger(fig2_summaries, launch_file):
    # every dependent publisher of Fig. 2 is driven by each of its node's
    # inputs (relay, scan_filter: one input; merger: both callbacks
    # publish), so the trigger model gives the paper's sizes
    system = _system(fig2_summaries, launch_file, {})
    result = impact_all(system, 'trigger')
    for row in result['nodes']:
        assert row['trigger_impact'] == row['paper_impact'] <= \
            row['traditional_impact']
    assert result['trigger_ratio'] == result['paper_ratio']
