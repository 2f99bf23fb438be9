# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Triggers, the trigger model of impact, and predicted rates.

Every expectation is written by hand from the sources in
test_workspaces/triggers/src/trig_nodes/src (see the EXPECT comments there).
"""

import json

from colcon_rsia.subverb.rates import parse_set_rates
from colcon_rsia.summary.store import find_summaries
from colcon_rsia.summary.store import read_summary
from colcon_rsia.system.graph import build_graph
from colcon_rsia.system.impact import rate_impact
from colcon_rsia.system.impact import traditional_impact
from colcon_rsia.system.rates import predict_rates
from colcon_rsia.system.rates import what_if
from conftest import analyze_source
from conftest import build_workspace
from conftest import WORKSPACES
from helpers import colcon_json
import pytest

SRC = WORKSPACES / 'triggers' / 'src'


def node(name):
    return f'trig_nodes/{name}'


@pytest.fixture(scope='session')
def triggers_workspace(tmp_path_factory):
    workspace = build_workspace(SRC, tmp_path_factory.mktemp('triggers'))
    assert workspace.returncode == 0, workspace.stdout + workspace.stderr
    return workspace


@pytest.fixture(scope='session')
def system(triggers_workspace):
    summaries = [read_summary(path) for path in find_summaries(
        str(triggers_workspace.build_base)).values()]
    return build_graph(summaries)


def _publishers(workspace):
    summary = workspace.summary('trig_nodes')
    return {p['topic']: p for n in summary['nodes'] for p in n['publishers']}


def test_triggers_in_the_summary(triggers_workspace):
    publishers = _publishers(triggers_workspace)

    def triggers(topic):
        return sorted((t['kind'], t['name'], t['every'], t['sync'] is not None)
                      for t in publishers[topic]['triggers'])
    # the tf listener and the cache-only /joint_states callback: no trigger
    assert triggers('/scan_relayed') == [('subscriber', '/scan', None, False)]
    # both inputs of the synchronizer, through its one callback
    assert triggers('/fused') == [
        ('subscriber', '/image', None, True),
        ('subscriber', '/scan_relayed', None, True)]
    assert triggers('/image_third') == [('subscriber', '/image', 3, False)]
    # the /enable flag is shared state, not a trigger (the documented miss)
    assert triggers('/gated') == [('subscriber', '/image', None, False)]
    assert triggers('/status') == [
        ('subscriber', '/joint_states', None, False),
        ('subscriber', '/scan', None, False)]
    busy = publishers['/busy']['triggers']
    assert [t['kind'] for t in busy] == ['all']
    assert 'main' in busy[0]['detail'] and \
        'src/busy_loop.cpp:25' in busy[0]['detail']
    # evidence: the callback and the path to the publish call
    status = {t['name']: t for t in publishers['/status']['triggers']}
    assert status['/scan']['detail'] == \
        'onScan publishes at src/mixer.cpp:16 <- src/mixer.cpp:21'
    assert status['/scan']['location'] == 'src/mixer.cpp:34'
    # independent publishers have no triggers; their own rate is kept
    for topic, rate, paced_by in (('/scan', 10, 'rate_loop'),
                                  ('/image', 30, 'timer'),
                                  ('/joint_states', 100, 'rate_loop'),
                                  ('/tf', 50, 'timer'),
                                  ('/enable', 1, 'timer')):
        assert publishers[topic]['triggers'] is None
        assert (publishers[topic]['paced_rate_hz'],
                publishers[topic]['paced_by']) == (rate, paced_by)


def test_graph_json_has_resolved_triggers(triggers_workspace):
    graph = colcon_json(triggers_workspace, 'graph')
    got = {p['resolved']: p.get('triggers')
           for n in graph['nodes'] for p in n['publishers']}
    assert got == {
        '/scan': None, '/image': None, '/joint_states': None, '/tf': None,
        '/enable': None, '/scan_relayed': ['/scan'],
        '/fused': ['/image', '/scan_relayed'], '/image_third': ['/image'],
        '/gated': ['/image'], '/status': ['/joint_states', '/scan'],
        '/busy': ['*']}


# changed node -> (traditional, paper, trigger) impact sets, by hand
IMPACT = {
    'lidar': (['fusion', 'mixer', 'monitor', 'scan_relay'],) * 3,
    'camera': (['decimator', 'fusion', 'gate', 'monitor'],) * 3,
    # /joint_states reaches scan_relay, whose /scan_relayed only /scan
    # triggers: fusion is out of the trigger set
    'joints': (['busy_loop', 'fusion', 'mixer', 'monitor', 'scan_relay'],
               ['busy_loop', 'fusion', 'mixer', 'monitor', 'scan_relay'],
               ['busy_loop', 'mixer', 'monitor', 'scan_relay']),
    # the tf hub: scan_relay only listens
    'tf_pub': (['fusion', 'monitor', 'scan_relay'],
               ['fusion', 'monitor', 'scan_relay'], ['scan_relay']),
    # the trigger model's miss: /enable gates /gated through shared state,
    # so a change of enabler does reach monitor, but only the paper says so
    'enabler': (['gate', 'monitor'], ['gate', 'monitor'], ['gate']),
    'scan_relay': (['fusion', 'monitor'],) * 3,
    'busy_loop': (['monitor'],) * 3,
}


@pytest.mark.parametrize('changed', sorted(IMPACT))
def test_impact_under_both_models(system, changed):
    traditional, paper, trigger = IMPACT[changed]
    assert traditional_impact(system, [node(changed)]) == \
        [node(n) for n in traditional]
    assert rate_impact(system, [node(changed)]) == [node(n) for n in paper]
    assert rate_impact(system, [node(changed)], 'trigger') == \
        [node(n) for n in trigger]


def test_impact_all_three_sizes_and_ratios(triggers_workspace):
    result = colcon_json(
        triggers_workspace, 'impact', '--all', '--model', 'trigger')
    got = {row['id']: (row['traditional_impact'], row['paper_impact'],
                       row['trigger_impact'], row['rate_impact'])
           for row in result['nodes']}
    want = {node(name): (len(t), len(p), len(g), len(g))
            for name, (t, p, g) in IMPACT.items()}
    # the last four publish to monitor only
    for name in ('fusion', 'decimator', 'gate', 'mixer'):
        want[node(name)] = (1, 1, 1, 1)
    assert got == want
    # 25 traditional, 25 paper, 21 trigger over 11 nodes
    assert (result['paper_ratio'], result['trigger_ratio'],
            result['trigger_to_paper'], result['ratio']) == \
        (1.0, 0.84, 0.84, 0.84)
    rows = {row['id']: row for row in result['nodes']}
    assert rows[node('enabler')]['not_triggered'] == [{
        'node': node('gate'), 'via': '/enable', 'topic': '/gated',
        'triggers': [{'trigger': '/image', 'evidence':
                      'Gate::onImage publishes at src/gate.cpp:29 '
                      '(src/gate.cpp:17)'}]}]
    assert 'not_triggered' not in rows[node('lidar')]


def test_impact_text_explains_the_difference(triggers_workspace):
    result = triggers_workspace.colcon(
        'rsia', 'impact', '--base-paths', str(triggers_workspace.src),
        '--changed', node('tf_pub'), '--model', 'trigger', check=True)
    assert 'rate impact: 1 node; traditional: 3 (trigger model; ' \
        'paper 3, trigger 1)' in result.stdout
    assert 'paper model only: trig_nodes/fusion, trig_nodes/monitor' in \
        result.stdout
    assert 'trig_nodes/scan_relay: /tf does not trigger /scan_relayed; ' \
        'triggered by /scan' in result.stdout
    table = triggers_workspace.colcon(
        'rsia', 'impact', '--base-paths', str(triggers_workspace.src),
        '--all', check=True)
    assert 'ratio to traditional: paper 1, trigger 0.84; trigger / paper ' \
        '0.84' in table.stdout
    assert 'trig_nodes/tf_pub: trigger 1 < paper 3:' in table.stdout


# every topic's rate, by hand (None: unknown)
RATES = {
    '/scan': (10, 'Rate loop'),
    '/image': (30, 'timer'),
    '/joint_states': (100, 'Rate loop'),
    '/tf': (50, 'timer'),
    '/enable': (1, 'timer'),
    '/scan_relayed': (10, 'follows /scan'),
    '/fused': (10, 'slowest of /image, /scan_relayed'),
    '/image_third': (10, '/image / 3'),
    '/gated': (30, 'follows /image'),
    '/status': (110, 'sum of /scan, /joint_states'),
    '/busy': (None, 'unknown'),       # an unpaced loop in main
    '/tf_static': (None, 'unknown'),  # nobody publishes it
}


def test_rates_json(triggers_workspace):
    result = colcon_json(triggers_workspace, 'rates')
    assert result['schema'] == 'colcon-rsia/rates@1'
    got = {t['name']: (t['hz'], t['source']) for t in result['topics']}
    assert got == RATES
    chains = {t['name']: t['chain'] for t in result['topics']}
    assert chains['/scan_relayed'] == [
        '/scan: 10 Hz Rate loop (trig_nodes/lidar src/lidar.cpp:10)',
        '/scan_relayed: follows /scan (trig_nodes/scan_relay '
        'src/scan_relay.cpp:21)']
    assert 'main root main reaches the publish site' in chains['/busy'][0]


def test_what_if_a_rate_is_set(system):
    changes, kept = what_if(system, set_rates={'/scan': 20})
    assert [(c['topic'], c['from'], c['to']) for c in changes] == [
        ('/fused', 10, 20), ('/scan', 10, 20), ('/scan_relayed', 10, 20),
        ('/status', 110, 120)]
    assert kept == []
    # the camera at 15 Hz: /fused now follows /image, the slower input
    rates = predict_rates(system, set_rates={'/image': 15})
    assert (rates['/fused'].hz, rates['/image_third'].hz,
            rates['/gated'].hz) == (10, 5, 15)
    rates = predict_rates(system, set_rates={'/image': 6})
    assert rates['/fused'].hz == 6


def test_what_if_a_node_changes(triggers_workspace):
    result = triggers_workspace.colcon(
        'rsia', 'rates', '--base-paths', str(triggers_workspace.src),
        '--changed', node('tf_pub'), '--model', 'trigger', check=True)
    assert '  /tf: 50 Hz -> may change' in result.stdout
    assert '  /scan_relayed keeps 10 Hz: trig_nodes/scan_relay -> ' \
        '/scan_relayed (not triggered by /tf) stops /tf' in result.stdout
    data = colcon_json(triggers_workspace, 'rates', '--changed',
                       node('joints'))
    assert [(c['topic'], c['to'], c['may_change'])
            for c in data['changes']] == [
        ('/joint_states', None, True), ('/status', None, True)]
    # the paper model crosses every dependent edge: nothing is kept
    assert data['kept'] == []


def test_set_rate_errors(triggers_workspace):
    assert parse_set_rates(['/a=2.5', '/b=0']) == ({'/a': 2.5, '/b': 0}, None)
    for bad in ('scan=3', '/scan=fast', '/scan=-1', '/scan'):
        rates, error = parse_set_rates([bad])
        assert rates is None and 'expected /TOPIC=HZ' in error
    result = triggers_workspace.colcon(
        'rsia', 'rates', '--base-paths', str(triggers_workspace.src),
        '--set-rate', '/nope=3')
    assert result.returncode != 0
    assert 'no topic /nope in the system' in result.stderr


def test_report_shows_both_models(triggers_workspace, tmp_path):
    triggers_workspace.colcon(
        'rsia', 'report', '--base-paths', str(triggers_workspace.src),
        '--output', str(tmp_path), '--model', 'trigger', '--changed',
        node('joints'), check=True)
    summary = (tmp_path / 'summary.md').read_text()
    assert '(ratio 0.84; paper model 1, trigger model 0.84)' in summary
    # names in the reason are inline code (never Markdown)
    assert '| `trig_nodes/fusion` | traditional only | held: `/joint_states` ' \
        'does not trigger `/scan_relayed` of `trig_nodes/scan_relay` |' \
        in summary
    dot = (tmp_path / 'graph.dot').read_text()
    assert '"topic:/image_third" [label="/image_third\\n10 Hz (/image / 3)"' \
        in dot
    assert '"node:trig_nodes/scan_relay" -> "topic:/scan_relayed" ' \
        '[label="triggered by /scan"];' in dot
    impact = json.loads((tmp_path / 'impact.json').read_text())
    assert impact['model'] == 'trigger'
    assert impact['rate_impact'] == impact['trigger_impact'] == [
        node(n) for n in IMPACT['joints'][2]]


def test_no_summary_triggers_means_every_input(system):
    """A summary written before triggers: the paper's rule, said so."""
    from dataclasses import replace
    instance = system.instances[node('scan_relay')]
    entry = instance.publishers[0]
    old = replace(entry['publisher'], triggers=None)
    from colcon_rsia.system.graph import resolve_triggers
    assert resolve_triggers(instance, old) == [('*', None)]


# the classic talker: no inputs, a ros::Rate loop of 10 Hz
TALKER = r"""
#include "ros/ros.h"
#include "std_msgs/String.h"
#include <sstream>

int main(int argc, char **argv)
{
  ros::init(argc, argv, "talker");
  ros::NodeHandle n;
  ros::Publisher chatter_pub = n.advertise<std_msgs::String>("chatter", 1000);
  ros::Rate loop_rate(10);
  int count = 0;
  while (ros::ok())
  {
    std_msgs::String msg;
    std::stringstream ss;
    ss << "hello world " << count;
    msg.data = ss.str();
    chatter_pub.publish(msg);
    ros::spinOnce();
    loop_rate.sleep();
    ++count;
  }
  return 0;
}
"""


def test_a_talker_without_inputs_has_the_rate_of_its_loop(tmp_path):
    summary = analyze_source(tmp_path, 'talk', TALKER, file='src/talker.cpp')
    [node] = summary.nodes
    [publisher] = node.publishers
    # independent because the node has no inputs; before, rate_hz was null
    # for every no_subscribers publisher
    assert (publisher.label, publisher.pattern, publisher.rate_hz) == (
        'independent', 'no_subscribers', 10.0)
    assert (publisher.paced_rate_hz, publisher.paced_by) == (10.0, 'rate_loop')
