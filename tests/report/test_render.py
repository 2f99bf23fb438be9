# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""One output layer: ``system`` computes, ``render`` writes, ``--format`` once.

The renderers are fed result documents written here by hand; the text
each must give is counted out from them.
"""

import ast
import json
from pathlib import Path

from colcon_rsia.package import call_sites
from colcon_rsia.package import coverage
from colcon_rsia.render import JSON
from colcon_rsia.render import TEXT
from colcon_rsia.render.check import render_check
from colcon_rsia.render.coverage import ANALYSED
from colcon_rsia.render.coverage import PUBLISHER
from colcon_rsia.render.coverage import render_coverage
from colcon_rsia.render.coverage import SUBSCRIBER
from colcon_rsia.render.coverage import total_line
from colcon_rsia.render.graph import graph_to_dot
from colcon_rsia.render.graph import render_graph
from colcon_rsia.render.impact import render_impact
from colcon_rsia.render.impact import render_impact_all
from colcon_rsia.render.rates import render_rates
from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.nodes import LabelledPublisher
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.nodes import NodeSubscriber
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.store import write_summary
from colcon_rsia.system.graph import build_graph
from conftest import run_colcon
import pytest

PACKAGE_DIR = Path(__file__).resolve().parents[2] / 'colcon_rsia'


def _parse(path):
    return ast.parse(path.read_text(), str(path))


def _called_name(call):
    function = call.func
    if isinstance(function, ast.Attribute):
        return function.attr
    return function.id if isinstance(function, ast.Name) else None


# the names renderers have: a function of system/ so named writes output
RENDERER_SUFFIXES = ('_to_text', '_to_dot', '_text')


def _output_written(directory):
    """Where the modules under `directory` write output or render it."""
    wrong = []
    for path in sorted(directory.rglob('*.py')):
        where = path.relative_to(directory)
        for node in ast.walk(_parse(path)):
            if isinstance(node, ast.Call):
                name = _called_name(node)
                keywords = {k.arg: k.value for k in node.keywords}
                # a note on stderr is no output: stdout stays the answer's
                to_stderr = isinstance(keywords.get('file'), ast.Attribute) \
                    and keywords['file'].attr == 'stderr'
                if name == 'print' and not to_stderr:
                    wrong.append(f'{where}:{node.lineno}: print to stdout')
                elif name in ('printable_lines', 'dumps', 'dump'):
                    wrong.append(f'{where}:{node.lineno}: {name}()')
            elif isinstance(node, ast.Attribute) and \
                    node.attr == 'stdout' and \
                    isinstance(node.value, ast.Name) and node.value.id == 'sys':
                wrong.append(f'{where}:{node.lineno}: sys.stdout')
            elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) \
                    and (node.name.endswith(RENDERER_SUFFIXES) or
                         node.name.startswith('render')):
                wrong.append(f'{where}:{node.lineno}: renderer {node.name}')
    return wrong


def test_system_computes_and_never_writes_output():
    assert _output_written(PACKAGE_DIR / 'system') == []


def test_the_output_check_finds_what_it_forbids(tmp_path):
    (tmp_path / 'bad.py').write_text(
        'import json\n'
        'import sys\n'
        'def rates_to_text(r):\n'
        '    print(r)\n'
        '    print(r, file=sys.stderr)\n'
        '    sys.stdout.write(json.dumps(r))\n')
    assert sorted(_output_written(tmp_path)) == [
        'bad.py:3: renderer rates_to_text', 'bad.py:4: print to stdout',
        'bad.py:6: dumps()', 'bad.py:6: sys.stdout']


def test_format_option_is_declared_only_in_the_shared_arguments():
    declared = sorted(
        str(path.relative_to(PACKAGE_DIR))
        for path in PACKAGE_DIR.rglob('*.py')
        for node in ast.walk(_parse(path))
        if isinstance(node, ast.Constant) and node.value == '--format')
    assert declared == ['subverb/arguments.py']


@pytest.mark.parametrize('subverb', [
    'graph', 'impact', 'rates', 'check', 'coverage', 'problems'])
def test_every_subverb_takes_the_shared_format_option(tmp_path, subverb):
    result = run_colcon(['rsia', subverb, '--help'], cwd=tmp_path,
                        check=True)
    choices = '{text,json,dot}' if subverb == 'graph' else '{text,json}'
    text = ' '.join(result.stdout.split())
    assert f'--format {choices} Output format (default: text)' in text


def test_a_format_the_result_has_no_renderer_for_is_refused(tmp_path):
    result = run_colcon(['rsia', 'impact', '--all', '--format', 'dot'],
                        cwd=tmp_path)
    assert result.returncode != 0
    assert "argument --format: invalid choice: 'dot'" in result.stderr


def _two_nodes():
    """p/a publishes /x from a 10 Hz timer; p/b reads it, writes /y."""
    a = Node(
        id='p/a', package='p', executable='a', kind='executable',
        publishers=[LabelledPublisher(
            topic='/x', topic_is_literal=True, msg_type='M', api='adv',
            handle='h', namespace='', location='src/a.cpp:5',
            label=INDEPENDENT, pattern='timer', rate_hz=10.0)])
    b = Node(
        id='p/b', package='p', executable='b', kind='executable',
        publishers=[LabelledPublisher(
            topic='y', topic_is_literal=True, msg_type='M', api='adv',
            handle='h', namespace='', location='src/b.cpp:12',
            label=DEPENDENT, pattern='none', rate_hz=None)],
        subscribers=[NodeSubscriber(
            topic='/x', topic_is_literal=True, msg_type='M', api='sub',
            callback='cb', namespace='', location='src/b.cpp:9')])
    return PackageSummary(
        package='p', path='/p', tool_version='0', nodes=[a, b])


GRAPH_TEXT = """\
p/a (executable, /a)
  publishes /x [independent: timer 10 Hz] src/a.cpp:5
p/b (executable, /b)
  publishes /y [dependent: none] src/b.cpp:12
  subscribes /x -> cb src/b.cpp:9
"""


def test_graph_text_lists_each_node_with_its_edges():
    assert render_graph(build_graph([_two_nodes()]), TEXT) == GRAPH_TEXT


def test_graph_dot_colours_the_impact_and_dashes_independent_edges():
    system = build_graph([_two_nodes()])
    # p/b's edge follows every input (no triggers recorded): no label
    assert graph_to_dot(system, changed={'p/a'}, rate_impact={'p/b'}) == """\
digraph rsia {
  rankdir=LR;
  node [fontname="Helvetica", fontsize=10];
  "node:p/a" [label="p/a", shape=ellipse, style=filled, fillcolor="#f4a261"];
  "node:p/b" [label="p/b", shape=ellipse, style=filled, fillcolor="#e76f51"];
  "topic:/x" [label="/x", shape=box];
  "topic:/y" [label="/y", shape=box];
  "node:p/a" -> "topic:/x" [style=dashed, label="independent"];
  "node:p/b" -> "topic:/y";
  "topic:/x" -> "node:p/b";
}
"""


def test_graph_json_is_the_graph_document_indented_and_sorted():
    text = render_graph(build_graph([_two_nodes()]), JSON)
    document = json.loads(text)
    assert document['schema'] == 'colcon-rsia/graph@1'
    assert [t['name'] for t in document['topics']] == ['/x', '/y']
    lines = text.splitlines()
    # keys sorted, two spaces a level, one line break at the end
    assert (lines[0], lines[1], lines[-1]) == ('{', '  "nodes": [', '}')
    assert text.endswith('}\n') and not text.endswith('\n\n')


def test_graph_of_the_colcon_script_comes_from_the_renderer(tmp_path):
    build_base = tmp_path / 'build'
    write_summary(str(build_base / 'p'), _two_nodes())
    result = run_colcon(
        ['rsia', 'graph', '--build-base', str(build_base)], cwd=tmp_path,
        check=True)
    assert result.stdout == GRAPH_TEXT


UNTRIGGERED = {
    'node': 'p/b', 'via': '/x', 'topic': '/z',
    'triggers': [{'trigger': '/w', 'evidence': 'callback cb (src/b.cpp:3)'}]}


def test_impact_text_gives_sizes_sets_and_where_the_trigger_model_stops():
    result = {
        'schema': 'colcon-rsia/impact@1', 'changed': ['p/a'],
        'model': 'trigger', 'rate_impact': ['p/b'],
        'traditional_impact': ['p/b', 'p/c'],
        'paper_impact': ['p/b', 'p/c'], 'trigger_impact': ['p/b'],
        'not_triggered': [UNTRIGGERED]}
    assert render_impact(result, TEXT, traditional=True) == """\
changed: p/a
rate impact: 1 node; traditional: 2 (trigger model; paper 2, trigger 1)
  p/b
traditional impact:
  p/b
  p/c
paper model only: p/c
the trigger model stops at (the paper model crosses):
  p/b: /x does not trigger /z; triggered by /w (callback cb (src/b.cpp:3))
"""
    assert 'traditional impact:' not in render_impact(result, TEXT)
    assert json.loads(render_impact(result, JSON)) == result


def test_impact_all_text_is_a_table_with_averages_and_ratios():
    result = {
        'schema': 'colcon-rsia/impact-all@1', 'model': 'paper',
        'nodes': [{'id': 'p/a', 'rate_impact': 2, 'traditional_impact': 3,
                   'paper_impact': 2, 'trigger_impact': 1,
                   'not_triggered': [UNTRIGGERED]}],
        'ratio': 0.667, 'paper_ratio': 0.667, 'trigger_ratio': 0.333,
        'trigger_to_paper': 0.5, 'average_rate_impact': 2.0,
        'average_traditional_impact': 3.0, 'average_paper_impact': 2.0,
        'average_trigger_impact': 1.0}
    assert render_impact_all(result, TEXT) == (
        'node  traditional  paper  trigger\n'
        'p/a' + ' ' * 13 + '3' + ' ' * 6 + '2' + ' ' * 8 + '1\n'
        'average: traditional 3, paper 2, trigger 1 over 1 nodes\n'
        'ratio to traditional: paper 0.667, trigger 0.333; '
        'trigger / paper 0.5\n'
        'p/a: trigger 1 < paper 2:\n'
        '    p/b: /x does not trigger /z; triggered by /w '
        '(callback cb (src/b.cpp:3))\n')


def test_rates_text_gives_rates_sources_and_the_what_if():
    result = {
        'schema': 'colcon-rsia/rates@1', 'model': 'paper',
        'set_rates': {'/a': 20.0}, 'changed': [],
        'topics': [
            {'name': '/a', 'hz': 20.0, 'source': 'set',
             'chain': ['/a: 20 Hz (--set-rate)']},
            {'name': '/long_topic', 'hz': None, 'source': 'unknown',
             'chain': ['/long_topic: no publisher in the system']}],
        'changes': [{'topic': '/a', 'from': 10.0, 'to': 20.0,
                     'may_change': False, 'source': 'set'}],
        'kept': [{'topic': '/c', 'hz': 5.0, 'node': 'p/n', 'via': '/a',
                  'edge': 'p/n -> /c (independent)'}]}
    # the names take the width of the longest, the rates ten characters
    assert render_rates(result, TEXT) == (
        '/a' + ' ' * 16 + '20 Hz  set\n'
        '/long_topic' + ' ' * 5 + 'unknown  unknown\n'
        + ' ' * 25 + '(/long_topic: no publisher in the system)\n'
        'what if: /a=20 Hz\n'
        '  /a: 10 Hz -> 20 Hz\n'
        '  /c keeps 5 Hz: p/n -> /c (independent) stops /a\n')
    assert json.loads(render_rates(result, JSON)) == result


def test_check_text_of_two_bags_lists_topics_counts_and_misses():
    result = {
        'schema': 'colcon-rsia/check@1', 'tolerance': 0.15,
        'changed': ['p/a'], 'model': 'paper',
        'topics': [
            {'name': '/x', 'before_hz': 10.0, 'after_hz': 5.0,
             'predicted_hz': 10.0, 'status': 'changed',
             'predicted_to_change': True},
            {'name': '/y', 'before_hz': 2.0, 'after_hz': 1.0,
             'predicted_hz': None, 'status': 'changed',
             'predicted_to_change': False}],
        'counts': {'changed': 2},
        'unexpected_changes': [{'topic': '/y', 'before_hz': 2.0,
                                'after_hz': 1.0, 'kept_by': []}],
        'changes_outside_the_model': [],
        'predicted_but_unchanged': [{'topic': '/z', 'before_hz': 1.0,
                                     'after_hz': 1.0}]}
    assert render_check(result, TEXT) == (
        '/x' + ' ' * 12 + '10 Hz -> 5 Hz  predicted' + ' ' * 6 +
        '10 Hz  changed (predicted: may change)\n'
        '/y' + ' ' * 13 + '2 Hz -> 1 Hz  predicted' + ' ' * 10 +
        '-  changed\n'
        '2 changed (tolerance 15%)\n'
        'changed: p/a (paper model)\n'
        '  unexpected change of /y: 2 Hz -> 1 Hz '
        '(no edge of the model reaches it)\n'
        '  predicted to change, unchanged: /z (1 Hz)\n')
    assert json.loads(render_check(result, JSON)) == result


def _counts(sites, in_nodes, in_units_only, from_tokens):
    return {'sites': sites, 'in_nodes': in_nodes,
            'in_units_only': in_units_only, 'from_tokens': from_tokens}


COVERAGE = {
    'schema': 'colcon-rsia/coverage@1',
    'packages': [
        {'package': 'p', 'status': 'analysed', 'has_coverage': True,
         'units': 4, 'units_with_errors': 1, 'units_losing_calls': 1,
         'call_sites': {'publisher': _counts(3, 2, 1, 0),
                        'subscriber': _counts(1, 1, 0, 1)},
         'missed': [{'file': 'src/a.cpp', 'line': 7, 'role': 'publisher',
                     'api': 'ros::NodeHandle::advertise'}],
         'unresolved_topics': [{}], 'unnamed_nodes': [], 'repairs': []},
        {'package': 'q', 'status': 'failed', 'error': 'boom'}],
    'total': {
        'packages': 2, 'failed': 1, 'not_analysed': 0, 'units': 4,
        'units_with_errors': 1, 'units_losing_calls': 1,
        'unresolved_topics': 1, 'unnamed_nodes': 0, 'percent': 75.0,
        'call_sites': {'publisher': _counts(3, 2, 1, 0),
                       'subscriber': _counts(1, 1, 0, 1)},
        'repairs': {}}}
TOTAL_LINE = (
    'rsia: coverage 75.0% of 4 publisher/subscription call sites in a '
    'node (2/3 publishers, 1/1 subscriptions; 1 more only in code no node '
    'runs; 1 read from tokens where the parse failed); 1 of 4 translation '
    'units with errors in package code (1 of them losing calls); 1 '
    "packages failed; see 'colcon rsia coverage'")


def test_coverage_total_line():
    assert total_line(COVERAGE) == TOTAL_LINE


def test_coverage_text_is_a_table_then_the_total():
    header = ('package' + ' ' * 33 + '  units errors   lost       pub'
              '       sub unres. unnamed\n')
    row = ('p' + ' ' * 39 + '      4      1      1       2/3       1/1'
           '      1       0\n')
    failed = 'q' + ' ' * 39 + ' failed: boom\n'
    assert render_coverage(COVERAGE, TEXT) == \
        header + row + failed + TOTAL_LINE + '\n'
    assert render_coverage(COVERAGE, TEXT, missed=True, repairs=True) == \
        header + row + \
        '  missed publisher: src/a.cpp:7 (ros::NodeHandle::advertise)\n' + \
        failed + 'repairs by rule: none\n' + TOTAL_LINE + '\n'
    assert json.loads(render_coverage(COVERAGE, JSON)) == COVERAGE


def test_coverage_renderer_reads_the_names_the_analysis_writes():
    # render may not import the build-time code: its names of the
    # document's keys and states must be those the analysis uses
    assert (PUBLISHER, SUBSCRIBER, ANALYSED) == (
        call_sites.PUBLISHER, call_sites.SUBSCRIBER, coverage.ANALYSED)
