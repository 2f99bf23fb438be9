# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""`colcon rsia report`, `--since REF` and `--fail-on` on the system workspace.

The workspace is the session fixture of conftest (built once); reports are
written into tmp_path. `--since` runs on a git repository made in tmp_path
from a copy of the workspace sources, with summaries copied next to it
whose `path` points into the copy.
"""

import json
import os
import re
import shutil
import subprocess
import time

from colcon_rsia.render.graph import graph_to_json
from colcon_rsia.report import build_report
from colcon_rsia.report.html import CSP
from colcon_rsia.report.html import render_html
from colcon_rsia.report.layout import layered_layout
from colcon_rsia.report.markdown import render_summary
from colcon_rsia.report.writer import write_report
from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import PATTERN_NONE
from colcon_rsia.summary.nodes import Evidence
from colcon_rsia.summary.nodes import LabelledPublisher
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.nodes import NodeSubscriber
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.store import find_summaries
from colcon_rsia.summary.store import read_summary
from colcon_rsia.system.load import load_system
from colcon_rsia.system.since import changed_since
from colcon_rsia.system.since import ChangeError
from conftest import run_colcon
from conftest import WORKSPACES
from headless import artifacts_directory
from headless import Browser
from headless import chromium_for_test
import pytest
import yaml

EXPECTED = yaml.safe_load(
    (WORKSPACES / 'system' / 'expected.yaml').read_text())
LASER = 'sysbot_drivers/laser_driver'
LASER_CASE = next(c for c in EXPECTED['impact'] if c['changed'] == [LASER])
PACKAGES = ('sysbot_drivers', 'sysbot_navigation', 'sysbot_perception')
GIT_ENV = {
    'GIT_AUTHOR_NAME': 'rsia test', 'GIT_AUTHOR_EMAIL': 'rsia@example.com',
    'GIT_COMMITTER_NAME': 'rsia test',
    'GIT_COMMITTER_EMAIL': 'rsia@example.com',
    'GIT_CONFIG_NOSYSTEM': '1', 'GIT_CONFIG_GLOBAL': os.devnull,
}


def _summaries(workspace):
    return [read_summary(path) for path in
            find_summaries(str(workspace.build_base)).values()]


@pytest.fixture
def system(system_workspace):
    return load_system(_summaries(system_workspace))


def _report(system, directory, changed=None, **kwargs):
    reasons = {c: ['named in the test'] for c in changed or ()}
    return write_report(system, str(directory), changed=changed,
                        reasons=reasons, **kwargs)


# --- the files ---------------------------------------------------------------

def test_report_writes_every_file(system, tmp_path):
    written, notes = _report(system, tmp_path, [LASER])
    expected = {'index.html', 'graph.dot', 'graph.json', 'impact.json',
                'summary.md', 'graph.svg'}
    if shutil.which('dot'):
        assert notes == []
    else:
        assert notes == ["Graphviz dot is not on PATH: the page's graph is "
                         'drawn by the simple built-in layout (top to '
                         'bottom, no clusters)']
    assert set(written) == expected
    assert set(os.listdir(tmp_path)) == expected

    graph = json.loads((tmp_path / 'graph.json').read_text())
    assert graph == graph_to_json(system)
    assert graph['schema'] == 'colcon-rsia/graph@1'
    got = {n['id']: {p['resolved']: p['label'] for p in n['publishers']}
           for n in graph['nodes']}
    assert got == {k: dict(v['publishes'])
                   for k, v in EXPECTED['nodes'].items()}

    impact = json.loads((tmp_path / 'impact.json').read_text())
    assert impact == {
        'schema': 'colcon-rsia/impact@1',
        'changed': [LASER],
        'model': 'paper',
        'rate_impact': LASER_CASE['rate_impact'],
        'traditional_impact': LASER_CASE['traditional_impact'],
        'paper_impact': LASER_CASE['rate_impact'],
        'trigger_impact': LASER_CASE['rate_impact'],
        'not_triggered': [],
    }

    dot = (tmp_path / 'graph.dot').read_text()
    assert dot.startswith('digraph rsia {')
    assert f'"node:{LASER}" [label="{LASER}", shape=ellipse, style=filled, ' \
        'fillcolor="#f4a261"];' in dot
    assert '"node:sysbot_navigation/planner" [label=' \
        '"sysbot_navigation/planner", shape=ellipse, style=filled, ' \
        'fillcolor="#e76f51"];' in dot
    assert '"node:sysbot_navigation/controller" [label=' \
        '"sysbot_navigation/controller", shape=ellipse, style=filled, ' \
        'fillcolor="#e9c46a"];' in dot
    assert '"node:sysbot_navigation/planner" -> "topic:/plan" ' \
        '[style=dashed, label="independent"];' in dot

    # graph.svg: the page's drawing, standalone
    svg = (tmp_path / 'graph.svg').read_text()
    assert svg.startswith('<svg id="graph" xmlns="http://www.w3.org/2000/svg" ')
    assert '<style>' in svg and 'svg .edge.independent' in svg
    assert svg.count('<g class="vertex node') == len(system.instances)
    assert f'<g class="vertex node changed" data-name="{LASER}"' in svg
    assert svg.count('<path class="edge') == system.graph.number_of_edges()


def test_report_without_changes_has_no_impact(system, tmp_path):
    (tmp_path / 'impact.json').write_text('{"stale": true}')
    written, _ = _report(system, tmp_path)
    assert 'impact.json' not in written
    assert not (tmp_path / 'impact.json').exists()  # an old one is removed
    summary = (tmp_path / 'summary.md').read_text()
    assert 'No changed nodes were given' in summary
    # traditional, paper, trigger
    assert '| `sysbot_navigation/planner` | 4 | 3 | 3 |' in summary
    page = (tmp_path / 'index.html').read_text()
    assert 'No changed nodes were given' in page


def test_summary_md_for_a_pull_request(system):
    data = build_report(system, changed=[LASER],
                        reasons={LASER: ['src/laser_driver.cpp changed']},
                        since='origin/main')
    summary = render_summary(data)
    lines = summary.splitlines()
    assert lines[0] == '### colcon-rsia: rate impact'
    assert '**Changed since `origin/main`:** 1 node' in lines
    assert f'- `{LASER}`: `src/laser_driver.cpp` changed' in lines
    assert '**Rate-aware impact: 2 nodes** (traditional data-flow ' \
        'impact: 5)' in lines
    rows = [line for line in lines if line.startswith('| `')]
    assert [r.split(' | ')[0][2:] for r in rows] == [
        f'`{LASER}`', '`sysbot_navigation/planner`',
        '`sysbot_perception/scan_filter`', '`sysbot_drivers/base_driver`',
        '`sysbot_navigation/controller`', '`sysbot_navigation/system_monitor`']
    assert '| `sysbot_perception/scan_filter` | rate-aware | via `/scan` of ' \
        f'`{LASER}` (changed node: relabelled dependent) |' in lines
    assert '| `sysbot_navigation/controller` | traditional only | data flow ' \
        'only: held by independent `/plan` of `sysbot_navigation/planner` ' \
        '(timer 5 Hz) |' in lines
    assert '- `/plan` of `sysbot_navigation/planner` (timer 5 Hz): holds ' \
        '`sysbot_navigation/controller`, `sysbot_navigation/system_monitor`' \
        in lines
    assert '- `/filter_stats` of `sysbot_perception/scan_filter` ' \
        '(timer 1 Hz): holds `sysbot_navigation/system_monitor`' in lines
    assert 'ratio 0.467' in lines[-1]
    # link-free, HTML-free
    assert not re.search(r'https?://|\]\(|<[a-z]', summary)


def test_summary_md_when_nothing_changed(system):
    data = build_report(system, changed=[], since='HEAD~1')
    assert 'No analysed node changed since `HEAD~1`: no rate impact.' in \
        render_summary(data)


def _hostile_summary():
    evil = '<script>alert(1)</script>'
    publisher = LabelledPublisher(
        topic=f'/x{evil}', topic_is_literal=True, msg_type='std_msgs::"&',
        api='ros::NodeHandle::advertise', handle=None, namespace='',
        location=f'src/{evil}.cpp:3', label=DEPENDENT,
        pattern=PATTERN_NONE, rate_hz=None,
        evidence=[Evidence('path', 'src/a.cpp:1', f'"{evil}"')])
    subscriber = NodeSubscriber(
        topic=f'/x{evil}', topic_is_literal=True, msg_type=None,
        api='ros::NodeHandle::subscribe', callback=evil, namespace='',
        location='src/a.cpp:2')
    nodes = [
        Node(id=f'pkg/a{evil}', package='pkg', executable=f'a{evil}',
             kind='executable', publishers=[publisher]),
        Node(id='pkg/b', package='pkg', executable='b',
             kind='executable', subscribers=[subscriber])]
    return PackageSummary(package='pkg', path='/nowhere',
                          tool_version='0', nodes=nodes)


def test_html_escapes_every_text_from_the_summaries():
    system = load_system([_hostile_summary()])
    changed = ['pkg/a<script>alert(1)</script>']
    page = render_html(build_report(
        system, changed=changed, reasons={changed[0]: ['<b>why</b>']}))
    assert '<script>alert' not in page
    assert '<b>why' not in page
    assert '&lt;script&gt;alert(1)&lt;/script&gt;' in page
    assert page.count('<script>') == 1  # ours


def test_layout_is_deterministic_and_layered(system):
    first = layered_layout(system.graph)
    second = layered_layout(system.graph)
    assert first == second
    assert set(first.boxes) == set(system.graph.nodes)
    # the one cycle (planner -> /plan -> controller -> /cmd_vel ->
    # base_driver -> /odom -> planner) is broken by one reversed edge
    assert len(first.reversed_edges) == 1
    for source, target in system.graph.edges:
        a, b = first.boxes[source], first.boxes[target]
        if (source, target) in first.reversed_edges:
            assert b.layer < a.layer
        else:
            assert b.layer > a.layer
        # a long edge has a waypoint in every row it crosses
        assert len(first.waypoints[(source, target)]) == \
            abs(b.layer - a.layer) - 1
    rows = {}
    for box in first.boxes.values():
        rows.setdefault(box.layer, []).append(box)
    for boxes in rows.values():
        boxes.sort(key=lambda b: b.x)
        for left, right in zip(boxes, boxes[1:]):
            assert left.x + left.width < right.x  # no overlap


# --- the command line --------------------------------------------------------

def _rsia(workspace, *args):
    return workspace.colcon('rsia', *args, '--base-paths', str(workspace.src))


def test_report_subverb(system_workspace, tmp_path):
    out = tmp_path / 'report'
    result = _rsia(system_workspace, 'report', '--changed', LASER,
                   '--output', str(out))
    assert result.returncode == 0, result.stderr
    assert f'rsia: report written to {out}: ' in result.stdout
    assert json.loads((out / 'impact.json').read_text())['rate_impact'] == \
        LASER_CASE['rate_impact']
    assert f'- `{LASER}`: named with --changed' in \
        (out / 'summary.md').read_text()
    both = _rsia(system_workspace, 'report', '--changed', LASER, '--since',
                 'HEAD', '--output', str(out))
    assert both.returncode == 1  # a usage error: 2 is --fail-on's
    assert 'not allowed with argument' in both.stderr


def test_fail_on_exit_codes(system_workspace):
    hit = _rsia(system_workspace, 'impact', '--changed', LASER, '--fail-on',
                'sysbot_navigation/planner', 'sysbot_drivers/base_driver')
    assert hit.returncode == 2, hit.stderr
    assert 'rate impact: 2 nodes; traditional: 5' in hit.stdout  # printed
    assert 'rsia: the rate-aware impact set contains --fail-on node ' \
        'sysbot_navigation/planner' in hit.stderr
    # controller is in the traditional impact set only
    miss = _rsia(system_workspace, 'impact', '--changed', LASER,
                 '--fail-on', 'sysbot_navigation/controller',
                 '--format', 'json')
    assert miss.returncode == 0, miss.stderr
    assert json.loads(miss.stdout)['rate_impact'] == \
        LASER_CASE['rate_impact']
    unknown = _rsia(system_workspace, 'impact', '--changed', LASER,
                    '--fail-on', 'sysbot_navigation/plannr')
    assert unknown.returncode == 1
    assert "unknown node 'sysbot_navigation/plannr'" in unknown.stderr
    assert 'sysbot_navigation/planner' in unknown.stderr
    assert 'Traceback' not in unknown.stderr


# --- --since -----------------------------------------------------------------

def _git(repo, *args):
    env = dict(os.environ, **GIT_ENV)
    return subprocess.run(['git', *args], cwd=str(repo), env=env,
                          check=True, capture_output=True, text=True)


@pytest.fixture
def git_workspace(system_workspace, tmp_path):
    """A git repository with a copy of the sources, and summaries for it.

    ``build/<pkg>/rsia/summary.json`` are the fixture's summaries with
    ``path`` pointing into the copy: nothing is compiled again.
    """
    repo = tmp_path / 'repo'
    shutil.copytree(WORKSPACES / 'system' / 'src', repo / 'src')
    launch = repo / 'src' / 'sysbot_bringup' / 'launch' / 'robot.launch'
    launch.parent.mkdir(parents=True)
    launch.write_text(
        '<launch>\n'
        '  <node pkg="sysbot_drivers" type="laser_driver" name="laser"/>\n'
        '  <node pkg="sysbot_perception" type="scan_filter" '
        'name="scan_filter"/>\n'
        '</launch>\n')
    _git(repo, '-c', 'init.defaultBranch=main', 'init', '-q')
    _git(repo, 'add', '-A')
    _git(repo, 'commit', '-q', '-m', 'initial')
    build = tmp_path / 'build'
    for package in PACKAGES:
        data = system_workspace.summary(package)
        data['path'] = str(repo / 'src' / package)
        target = build / package / 'rsia' / 'summary.json'
        target.parent.mkdir(parents=True)
        target.write_text(json.dumps(data))
    return repo


def _touch(path, text='// changed\n'):
    with open(path, 'a') as h:
        h.write(text)


def _git_system(tmp_path, launch=None):
    summaries = [read_summary(path) for path in
                 find_summaries(str(tmp_path / 'build')).values()]
    return load_system(summaries, launch=launch)


def test_since_maps_changed_files_to_nodes(git_workspace, tmp_path):
    system = _git_system(tmp_path)
    assert changed_since(system, 'HEAD') == {}
    _touch(git_workspace / 'src/sysbot_drivers/src/laser_driver.cpp')
    _touch(git_workspace / 'src/sysbot_drivers/package.xml', '<!-- -->\n')
    (git_workspace / 'src/sysbot_perception/src/new.cpp').write_text('')
    # working-tree changes count; an untracked file and package.xml don't
    assert changed_since(system, 'HEAD') == {
        LASER: ['src/laser_driver.cpp changed']}
    _git(git_workspace, 'commit', '-q', '-am', 'change the laser driver')
    _touch(git_workspace / 'src/sysbot_navigation/src/planner.cpp')
    _git(git_workspace, 'rm', '-q',
         'src/sysbot_perception/src/obstacle_detector.cpp')
    # committed, working-tree and deleted files, against an older commit
    assert changed_since(system, 'HEAD~1') == {
        LASER: ['src/laser_driver.cpp changed'],
        'sysbot_navigation/planner': ['src/planner.cpp changed'],
        'sysbot_perception/obstacle_detector': [
            'src/obstacle_detector.cpp changed'],
    }


def test_since_a_changed_launch_file_changes_its_instances(
        git_workspace, tmp_path):
    launch = git_workspace / 'src/sysbot_bringup/launch/robot.launch'
    system = _git_system(tmp_path, launch=[str(launch)])
    assert sorted(system.instances) == ['/laser', '/scan_filter']
    assert changed_since(system, 'HEAD') == {}
    _touch(launch, '<!-- tuned -->\n')
    _touch(git_workspace / 'src/sysbot_drivers/src/laser_driver.cpp')
    reasons = changed_since(system, 'HEAD')
    assert sorted(reasons) == ['/laser', '/scan_filter']
    assert reasons['/laser'][0].startswith('launch file ')
    assert reasons['/laser'][0].endswith('robot.launch changed')
    assert 'src/laser_driver.cpp changed' in reasons['/laser']


def test_since_errors_are_one_sentence(git_workspace, tmp_path):
    system = _git_system(tmp_path)
    with pytest.raises(ChangeError, match='unknown revision'):
        changed_since(system, 'no-such-branch')
    with pytest.raises(ChangeError, match='not a git revision'):
        changed_since(system, '--output=/tmp/x')
    shutil.rmtree(git_workspace / '.git')
    with pytest.raises(ChangeError, match='not in a git repository'):
        changed_since(system, 'HEAD')


def _git_colcon(tmp_path, *args):
    return run_colcon(
        ['rsia', *args, '--build-base', str(tmp_path / 'build'),
         '--base-paths', str(tmp_path / 'repo' / 'src')], cwd=tmp_path)


def test_since_on_the_command_line(git_workspace, tmp_path):
    _touch(git_workspace / 'src/sysbot_drivers/src/laser_driver.cpp')
    result = _git_colcon(tmp_path, 'impact', '--since', 'HEAD',
                         '--format', 'json')
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == {
        'schema': 'colcon-rsia/impact@1', 'changed': [LASER],
        'model': 'paper',
        'rate_impact': LASER_CASE['rate_impact'],
        'traditional_impact': LASER_CASE['traditional_impact'],
        'paper_impact': LASER_CASE['rate_impact'],
        'trigger_impact': LASER_CASE['rate_impact'],
        'not_triggered': []}
    assert f'rsia: changed {LASER}: src/laser_driver.cpp changed' in \
        result.stderr
    failing = _git_colcon(tmp_path, 'impact', '--since', 'HEAD',
                          '--fail-on', 'sysbot_perception/scan_filter')
    assert failing.returncode == 2
    out = tmp_path / 'report'
    report = _git_colcon(tmp_path, 'report', '--since', 'HEAD', '--output',
                         str(out))
    assert report.returncode == 0, report.stderr
    summary = (out / 'summary.md').read_text()
    assert '**Changed since `HEAD`:** 1 node' in summary
    assert f'- `{LASER}`: `src/laser_driver.cpp` changed' in summary
    bad = _git_colcon(tmp_path, 'impact', '--since', 'no-such-branch')
    assert bad.returncode == 1
    assert '--since no-such-branch: unknown revision in the git ' \
        'repository' in bad.stderr
    assert 'Traceback' not in bad.stderr
    exclusive = _git_colcon(tmp_path, 'impact', '--since', 'HEAD', '--all')
    assert exclusive.returncode == 1
    assert 'not allowed with argument' in exclusive.stderr


# --- the page in a real browser ------------------------------------------------

ROWS_JS = """(function () {
  var rows = Array.prototype.slice.call(
    document.querySelectorAll('tr[data-filter]'));
  return {
    shown: rows.filter(function (r) { return !r.hidden; })
      .map(function (r) { return r.textContent.toLowerCase(); }),
    hidden: rows.filter(function (r) { return r.hidden; })
      .map(function (r) { return r.textContent.toLowerCase(); }),
    dimmed: Array.prototype.map.call(
      document.querySelectorAll('#graph g.vertex.dimmed'),
      function (g) { return g.getAttribute('data-name'); })
  };
})()"""

PAGE_JS = """(function () {
  // the drawing, without the view's pan and zoom
  var graph = document.getElementById('graph-view').getBBox();
  var box = document.getElementById('graph-box').getBoundingClientRect();
  var impact = document.querySelectorAll(
    '#graph g.vertex.changed, #graph g.vertex.rate');
  function classes(selector) {
    return Array.prototype.map.call(document.querySelectorAll(selector),
      function (e) { return e.getAttribute('data-name'); }).sort();
  }
  return {
    rendered: document.body.getAttribute('data-rendered'),
    rows: Number(document.body.getAttribute('data-rows')),
    nodeRows: document.querySelectorAll('#nodes tbody tr').length,
    topicRows: document.querySelectorAll('#topics tbody tr').length,
    vertices: document.querySelectorAll('#graph g.vertex').length,
    edges: document.querySelectorAll('#graph path.edge').length,
    dashed: getComputedStyle(
      document.querySelector('#graph path.edge.independent')).strokeDasharray,
    graph: [graph.width, graph.height],
    impactOnScreen: impact.length > 0 && Array.prototype.every.call(
      impact, function (v) {
        var r = v.getBoundingClientRect();
        return r.left >= box.left && r.right <= box.right &&
          r.top >= box.top && r.bottom <= box.bottom;
      }),
    impactRows: document.querySelectorAll('#all-impact tbody tr').length,
    bars: document.querySelectorAll('#all-impact .bar').length,
    overflow: document.documentElement.scrollWidth - window.innerWidth,
    changed: classes('#graph g.vertex.changed'),
    rate: classes('#graph g.vertex.rate'),
    traditional: classes('#graph g.vertex.traditional'),
    count: document.getElementById('filter-count').textContent
  };
})()"""

TYPE_JS = """(function () {
  var input = document.getElementById('filter');
  input.value = %s;
  input.dispatchEvent(new Event('input'));
  return document.body.getAttribute('data-shown-rows');
})()"""

CSP_JS = """new Promise(function (resolve) {
  document.addEventListener('securitypolicyviolation', function (e) {
    resolve(e.effectiveDirective + ' ' + e.blockedURI);
  });
  fetch('http://127.0.0.1:9/probe').catch(function () {});
})"""


def test_index_html_in_headless_chromium(system, tmp_path):
    executable = chromium_for_test()
    out = tmp_path / 'report'
    _report(system, out, [LASER])
    page = (out / 'index.html').read_text()
    # nothing to fetch: no remote src/href/url(), and a CSP that says so
    assert not re.search(r"""(src|href)\s*=\s*["']?\s*(https?:)?//""", page)
    assert not re.search(r'url\(\s*["\']?\s*(https?:)?//|@import', page)
    assert f'<meta http-equiv="Content-Security-Policy" content="' \
        f"{CSP.replace(chr(39), '&#x27;')}\">" in page
    graph = graph_to_json(system)
    node_rows = sum(max(1, len(n['publishers'])) for n in graph['nodes'])
    url = (out / 'index.html').as_uri()
    started = time.monotonic()
    with Browser(executable, str(tmp_path / 'profile')) as browser:
        browser.open(url + '#filter=scan_filter')
        preset = browser.evaluate(ROWS_JS)
        assert browser.evaluate(
            "document.getElementById('filter').value") == 'scan_filter'
        assert preset['hidden'] and preset['shown']
        assert all('scan_filter' in text for text in preset['shown'])
        assert not any('scan_filter' in text for text in preset['hidden'])

        browser.open('about:blank')
        browser.open(url)
        state = browser.evaluate(PAGE_JS)
        assert state['rendered'] == 'true'  # the inline script ran
        assert state['nodeRows'] == node_rows
        assert state['topicRows'] == len(graph['topics'])
        assert state['rows'] == node_rows + len(graph['topics']) + \
            len(EXPECTED['all'])
        assert state['count'] == f'{state["rows"]} of {state["rows"]} rows'
        assert state['vertices'] == len(system.instances) + \
            len(graph['topics'])
        assert state['edges'] == system.graph.number_of_edges()
        assert state['dashed'] not in ('', 'none')  # the CSS applied
        # laid out left to right: wider than high
        assert state['graph'][0] > 600 and state['graph'][1] > 150
        assert state['impactOnScreen']  # the first view shows the impact
        assert state['impactRows'] == len(EXPECTED['all'])
        assert state['bars'] == 2 * len(EXPECTED['all'])
        assert state['overflow'] <= 0  # the tables fit the window
        assert state['changed'] == [LASER]
        assert state['rate'] == LASER_CASE['rate_impact']
        assert state['traditional'] == sorted(
            set(LASER_CASE['traditional_impact']) -
            set(LASER_CASE['rate_impact']))

        shown = browser.evaluate(TYPE_JS % json.dumps('obstacle_detector'))
        rows = browser.evaluate(ROWS_JS)
        assert int(shown) == len(rows['shown']) >= 3
        assert all('obstacle_detector' in text for text in rows['shown'])
        assert not any('obstacle_detector' in text for text in rows['hidden'])
        assert 'sysbot_perception/obstacle_detector' not in rows['dimmed']
        assert LASER in rows['dimmed']
        browser.evaluate(TYPE_JS % json.dumps(''))
        assert browser.evaluate(ROWS_JS)['hidden'] == []

        browser.screenshot(str(artifacts_directory(tmp_path) / 'report.png'))
        assert browser.problems() == []
        # the page itself, twice; nothing else
        assert [r.split('#')[0] for r in browser.requests()] == [url, url]

        # the policy is enforced: a request is refused, never sent
        assert browser.evaluate(CSP_JS) == \
            'connect-src http://127.0.0.1:9/probe'
        assert not any(r.startswith('http') for r in browser.requests())
    seconds = time.monotonic() - started
    png = (artifacts_directory(tmp_path) / 'report.png').read_bytes()
    assert png.startswith(b'\x89PNG') and len(png) > 20000
    assert seconds < 60
