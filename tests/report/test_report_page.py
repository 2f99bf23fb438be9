# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The report on a generated 300-node system, in the browser and on paper.

The system is written as summaries (tests/synthetic_system.py; nothing is
compiled); the report is made by the command line. Layout checks read the
drawing; the page is opened in headless Chromium (tests/headless.py).
"""

import json
import os
import shutil
import time

from colcon_rsia.report import build_report
from colcon_rsia.report.drawing import apply_dot_layout
from colcon_rsia.report.drawing import draw_system
from colcon_rsia.report.drawing import plan_drawing
from colcon_rsia.report.html import render_html
from colcon_rsia.system.load import load_system
from conftest import run_colcon
from headless import artifacts_directory
from headless import Browser
from headless import chromium_for_test
import networkx as nx
import pytest
from synthetic_system import HUB_TOPIC
from synthetic_system import NODES_PER_PACKAGE
from synthetic_system import synthetic_summaries
from synthetic_system import write_synthetic_workspace

NODES = 300
# the page of 300 nodes must be usable this soon after navigation starts
LOAD_LIMIT_S = 10.0


def _needs_dot():
    if shutil.which('dot') is None:
        if os.environ.get('CI'):
            pytest.fail('Graphviz dot is not installed (.ci/install '
                        'installs it)')
        pytest.skip('Graphviz dot is not installed')


@pytest.fixture(scope='module')
def generated(tmp_path_factory):
    """The 300-node workspace and its report, made by the command line."""
    root = tmp_path_factory.mktemp('generated')
    (root / 'src').mkdir()
    changed = write_synthetic_workspace(root / 'build', NODES)
    result = run_colcon(
        ['rsia', 'report', '--base-paths', str(root / 'src'), '--changed',
         changed, '--output', str(root / 'report')], cwd=root)
    assert result.returncode == 0, result.stderr
    return root, changed


# --- the drawing ---------------------------------------------------------------

def test_the_layout_goes_left_to_right_in_clusters(generated):
    _needs_dot()
    system = load_system(synthetic_summaries(NODES))
    drawing, note = draw_system(system)
    assert note is None
    assert drawing.engine == 'dot'
    vertices = {v.key: v for v in drawing.vertices}
    # one cluster per package (eight nodes each; the last has four)
    packages = -(-NODES // NODES_PER_PACKAGE)
    assert sorted(c.label for c in drawing.clusters) == sorted(
        f'package pkg_{k:03d}' for k in range(packages))
    for cluster in drawing.clusters:
        for key in cluster.members:
            vertex = vertices[key]
            assert cluster.x <= vertex.x and \
                vertex.x + vertex.width <= cluster.x + cluster.width
            assert cluster.y <= vertex.y and \
                vertex.y + vertex.height <= cluster.y + cluster.height
            if vertex.vertex[0] == 'node':
                assert vertex.vertex[1].startswith(cluster.label[8:] + '/')
    # no two boxes overlap
    boxes = sorted(drawing.vertices, key=lambda v: v.x)
    for index, a in enumerate(boxes):
        for b in boxes[index + 1:]:
            if b.x >= a.x + a.width:
                break
            assert b.y >= a.y + a.height or a.y >= b.y + b.height, \
                (a.vertex, b.vertex)
    # data flows left to right: the edges on no cycle end to the right of
    # their start (on a cycle dot has to turn an edge round; between
    # clusters it turns a few more)
    drawn = nx.DiGraph((e.source, e.target) for e in drawing.edges)
    component = {}
    for index, members in enumerate(nx.strongly_connected_components(drawn)):
        component.update({key: index for key in members})
    acyclic = [e for e in drawing.edges
               if component[e.source] != component[e.target]]
    assert len(acyclic) > len(drawing.edges) / 2

    def centre(key):
        return vertices[key].x + vertices[key].width / 2
    forward = [e for e in acyclic if centre(e.target) > centre(e.source)]
    assert len(forward) >= 0.95 * len(acyclic)
    # every edge has a route from its source box to its target box
    for edge in drawing.edges:
        assert edge.path.startswith('M') and 'C' in edge.path


def test_a_hub_topic_is_drawn_in_each_cluster():
    system = load_system(synthetic_summaries(NODES))
    drawing = plan_drawing(system)
    copies = [v for v in drawing.vertices if v.vertex == ('topic', HUB_TOPIC)]
    # every package has /tf publishers (its nodes 1 and 5), so one copy
    # per package
    packages = -(-NODES // NODES_PER_PACKAGE)
    assert len(copies) == packages
    assert all(c.copies == packages for c in copies)
    assert len({c.cluster for c in copies}) == packages
    cluster_of = {v.key: v.cluster for v in drawing.vertices}
    hub_keys = {c.key for c in copies}
    hub_edges = [e for e in drawing.edges if {e.source, e.target} & hub_keys]
    # /tf: 75 publishers (i % 4 == 1) and 50 subscribers (i % 6 == 5)
    assert len(hub_edges) == 75 + 50
    for edge in hub_edges:
        assert cluster_of[edge.source] == cluster_of[edge.target]
    # every other topic once; every system edge drawn once
    assert len(drawing.vertices) == len(system.graph) - 1 + packages
    assert sorted(e.edge for e in drawing.edges) == sorted(system.graph.edges)


def test_without_dot_the_built_in_layout_draws_and_says_so(
        tmp_path, monkeypatch):
    system = load_system(synthetic_summaries(40))
    empty = tmp_path / 'bin'
    empty.mkdir()
    monkeypatch.setenv('PATH', str(empty))
    drawing, note = draw_system(system)
    assert note == "Graphviz dot is not on PATH: the page's graph is " \
        'drawn by the simple built-in layout (top to bottom, no clusters)'
    assert drawing.engine == 'built-in' and drawing.clusters == []
    assert all(e.path.startswith('M') for e in drawing.edges)
    page = render_html(build_report(system), drawing)
    assert 'laid out by the built-in layered layout' in page

    broken = tmp_path / 'broken-dot'
    broken.write_text('#!/bin/sh\necho "syntax error in line 1" >&2\n'
                      'exit 1\n')
    broken.chmod(0o755)
    drawing, note = draw_system(system, dot_executable=str(broken))
    assert note == 'dot failed (1): syntax error in line 1: ' \
        "the page's graph is drawn by the simple built-in layout (top to " \
        'bottom, no clusters)'
    assert drawing.engine == 'built-in'
    garbage = tmp_path / 'garbage-dot'
    garbage.write_text('#!/bin/sh\ncat > /dev/null\necho "{}"\n')
    garbage.chmod(0o755)
    drawing, note = draw_system(system, dot_executable=str(garbage))
    assert note.startswith("unexpected JSON from dot (KeyError('bb'))")
    assert drawing.engine == 'built-in'


def test_dot_json_is_read_with_y_downwards():
    system = load_system(synthetic_summaries(12))
    drawing = plan_drawing(system)
    first, second = drawing.vertices[0], drawing.vertices[1]
    # Graphviz: y upwards, points; box centres at (50, 90) and (150, 10)
    layout = {
        'bb': '0,0,200,100',
        'objects': [
            {'_gvid': 0, 'name': first.key, 'pos': '50,90'},
            {'_gvid': 1, 'name': second.key, 'pos': '150,10'}],
        'edges': []}
    drawing.edges = []
    apply_dot_layout(drawing, layout)
    assert (first.x + first.width / 2, first.y + first.height / 2) == \
        (62.0, 22.0)  # 12 px margin; 100 - 90 = 10 from the top
    assert (second.x + second.width / 2, second.y + second.height / 2) == \
        (162.0, 102.0)
    assert (drawing.width, drawing.height) == (224.0, 124.0)


# --- exit codes ------------------------------------------------------------------

def test_usage_errors_exit_1(generated):
    root, changed = generated
    base = ['--base-paths', str(root / 'src')]
    cases = [
        ['rsia', 'impact', *base, '--since'],                   # no value
        ['rsia', 'report', *base, '--output', 'x', '--bogus'],  # unknown
        ['rsia', 'impact', *base, '--changed', changed, '--format', 'xml'],
        ['rsia', 'impact', *base, '--changed', changed, '--all'],
        ['rsia', 'no-such-subverb'],
    ]
    for args in cases:
        result = run_colcon(args, cwd=root)
        assert result.returncode == 1, (args, result.stderr)
        assert 'error:' in result.stderr
        assert 'Traceback' not in result.stderr
    assert 'unrecognized arguments: --bogus' in run_colcon(
        cases[1], cwd=root).stderr
    # 2 stays --fail-on's
    reached = json.loads(
        (root / 'report' / 'impact.json').read_text())['rate_impact'][0]
    hit = run_colcon(['rsia', 'impact', *base, '--changed', changed,
                      '--fail-on', reached], cwd=root)
    assert hit.returncode == 2, hit.stderr
    assert run_colcon(['rsia', 'report', '--help'], cwd=root).returncode == 0


# --- the page in a real browser -------------------------------------------------

STATE_JS = """(function () {
  var box = document.getElementById('graph-box').getBoundingClientRect();
  function onScreen(element) {
    var r = element.getBoundingClientRect();
    return r.width > 0 && r.left >= box.left && r.right <= box.right &&
      r.top >= box.top && r.bottom <= box.bottom &&
      r.bottom <= window.innerHeight && r.right <= window.innerWidth;
  }
  var changed = document.querySelectorAll('#graph g.vertex.changed');
  return {
    rendered: document.body.getAttribute('data-rendered'),
    layout: document.getElementById('graph').getAttribute('data-layout'),
    scale: Number(document.getElementById('graph').getAttribute('data-scale')),
    transform: document.getElementById('graph-view').getAttribute('transform'),
    changed: Array.prototype.map.call(changed,
      function (v) { return v.getAttribute('data-name'); }),
    changedOnScreen: Array.prototype.every.call(changed, onScreen),
    changedFontPx: changed[0].querySelector('text').getBoundingClientRect()
      .height,
    vertices: document.querySelectorAll('#graph g.vertex').length,
    edges: document.querySelectorAll('#graph path.edge').length,
    overflow: document.documentElement.scrollWidth - window.innerWidth
  };
})()"""

SEARCH_JS = """(function () {
  var input = document.getElementById('graph-search');
  input.value = %s;
  input.dispatchEvent(new Event('input'));
  var svg = document.getElementById('graph');
  var found = svg.querySelector('g.vertex[data-name="' +
    svg.getAttribute('data-found') + '"]');
  var box = document.getElementById('graph-box').getBoundingClientRect();
  var r = found.getBoundingClientRect();
  return {
    found: svg.getAttribute('data-found'),
    outlined: found.classList.contains('match'),
    count: document.getElementById('graph-found').textContent,
    dx: (r.left + r.right) / 2 - (box.left + box.right) / 2,
    dy: (r.top + r.bottom) / 2 - (box.top + box.bottom) / 2
  };
})()"""

CLICK_JS = """(function () {
  var vertex = document.querySelector(
    '#graph g.vertex.node[data-name=%s] rect');
  vertex.dispatchEvent(new MouseEvent('click', {bubbles: true}));
  return document.getElementById('graph-panel').textContent;
})()"""

WHEEL_JS = """(function () {
  var box = document.getElementById('graph-box').getBoundingClientRect();
  document.getElementById('graph-box').dispatchEvent(new WheelEvent('wheel',
    {deltaY: %d, clientX: box.left + 100, clientY: box.top + 100,
     bubbles: true, cancelable: true}));
  return Number(document.getElementById('graph').getAttribute('data-scale'));
})()"""

COLLAPSE_JS = """(function () {
  var cluster = document.querySelector('#graph g.cluster');
  var key = cluster.getAttribute('data-cluster');
  cluster.querySelector('text').dispatchEvent(
    new MouseEvent('click', {bubbles: true}));
  var members = document.querySelectorAll(
    '#graph g.vertex[data-cluster="' + key + '"]');
  return {
    members: members.length,
    hidden: document.querySelectorAll(
      '#graph g.vertex.hidden[data-cluster="' + key + '"]').length,
    collapsed: cluster.classList.contains('collapsed')
  };
})()"""

SORT_JS = """(function () {
  var th = document.querySelectorAll('#all-impact thead th')[2];
  th.click();
  th.click();  // the second click: descending
  return Array.prototype.map.call(
    document.querySelectorAll('#all-impact tbody tr'),
    function (row) { return Number(row.cells[2].textContent); });
})()"""


def test_300_nodes_in_headless_chromium(generated, tmp_path):
    _needs_dot()
    executable = chromium_for_test()
    root, changed = generated
    page = root / 'report' / 'index.html'
    url = page.as_uri()
    system = load_system(synthetic_summaries(NODES))
    impact = json.loads((root / 'report' / 'impact.json').read_text())
    with Browser(executable, str(tmp_path / 'profile')) as browser:
        started = time.monotonic()
        browser.open(url)
        state = browser.evaluate(STATE_JS)
        load_s = time.monotonic() - started
        assert state['rendered'] == 'true'
        assert load_s < LOAD_LIMIT_S
        assert state['layout'] == 'dot'
        packages = -(-NODES // NODES_PER_PACKAGE)
        assert state['vertices'] == len(system.graph) - 1 + packages
        assert state['edges'] == system.graph.number_of_edges()
        # the first screen shows the changed node, large enough to read
        assert state['changed'] == [changed]
        assert state['changedOnScreen']
        assert state['changedFontPx'] >= 6
        # the tables fit the 1,400 px window
        assert state['overflow'] <= 0
        browser.screenshot(str(artifacts_directory(tmp_path) / 'report_300.png'))

        # search: a node far from the changed one is found and centred
        far = 'pkg_036/node_0290'
        found = browser.evaluate(SEARCH_JS % json.dumps('node_0290'))
        assert found['found'] == far and found['outlined']
        assert found['count'] == '1 of 1'
        assert abs(found['dx']) < 2 and abs(found['dy']) < 2
        # a topic too
        topic = browser.evaluate(SEARCH_JS % json.dumps('topic_0290'))
        assert topic['found'] == '/topic_0290' and topic['outlined']
        assert abs(topic['dx']) < 2 and abs(topic['dy']) < 2

        # zoom: the buttons and the wheel change the view's scale
        before = browser.evaluate(STATE_JS)['scale']
        browser.evaluate("document.getElementById('zoom-in').click()")
        after = browser.evaluate(STATE_JS)
        assert after['scale'] == pytest.approx(before * 1.4, rel=1e-3)
        assert after['transform'] != state['transform']
        assert browser.evaluate(WHEEL_JS % 200) < after['scale']
        browser.evaluate("document.getElementById('zoom-fit').click()")
        whole = browser.evaluate(STATE_JS)['scale']
        assert whole < before  # 300 nodes do not fit at reading size

        # a click on the changed node shows its evidence
        panel = browser.evaluate(CLICK_JS % json.dumps(changed))
        index = int(changed.rsplit('_', 1)[1])
        assert f'src/node_{index:04d}.cpp:40' in panel  # its publisher
        assert f'src/node_{index:04d}.cpp:60' in panel  # its timer
        assert 'changed' in panel

        collapsed = browser.evaluate(COLLAPSE_JS)
        assert collapsed['collapsed']
        assert collapsed['members'] == collapsed['hidden'] > 1

        rates = browser.evaluate(SORT_JS)
        assert rates == sorted(rates, reverse=True)
        assert rates[0] >= len(impact['rate_impact'])
        assert browser.problems() == []
        assert [r.split('#')[0] for r in browser.requests()] == [url]
