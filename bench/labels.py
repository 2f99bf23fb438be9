# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Score colcon-rsia against the hand-labelled development set.

For every label file of ``bench/labels/`` (one repository branch each,
see ``bench/labels/README.md``) this finds the corpus workspace of that
branch (``<corpus>/<name>``, table ``WORKSPACES`` below, where the corpus
is ``--corpus``, default ``corpus/`` next to this checkout; or
``--workspace LABELFILE=DIR``), checks that its commit (the workspace's
row of the corpus ``MANIFEST.md``) is the one the label file records, and
runs the tool the way users run it, from the workspace root, unbuilt,
with colcon's default base paths and an empty ``COLCON_HOME``::

    colcon rsia analyze --build-base build_labels
    colcon rsia graph --format json --build-base build_labels

(no launch file: every node runs once in the root namespace under its
default name, which is what the labels' ``resolved`` names assume). The
colcon is the one of the interpreter running this script. Analyses run
one at a time; ``--reuse`` skips ``analyze`` where the build base exists.

Matching, one to one (never two labelled items to one tool item):

- nodes: same package, and the label's ``executable`` equals the tool
  node's ``executable`` or its ``plugin_class`` (from the package summary);
  else the last part of the label's name (after ``::`` or ``/``) equals
  that of the tool node's id, executable or plugin class; else that of the
  tool node's ``name`` (a target whose installed name differs, a
  ``google_binary``); else the names equal without a ``.py`` suffix. Ties
  go to the tool node with the most labelled endpoints at their place,
  then to the same ``kind``, then to the most shared ``files``. The other
  tool nodes of the matched one's executable (one process making several
  ROS 2 nodes) that no labelled node took are scored with it.
- publishers, then subscriptions, of a matched node: same file and a line
  within 2; else the topic as written (the label's text before any
  `` (`` comment, a leading ``/`` ignored); else the same non-null
  resolved name. In each pass the closest pairs go first (same file, then
  same file name stem: a member declared in the header and constructed
  in the source, then line distance), and of pairs as close, those that
  agree on the name (endpoints a function makes at one place, once per
  call).

Scores (the table shows them as hit/total; the percentages are over the
denominators named here, everywhere):

- ``nodes``: labelled nodes matched to a tool node.
- ``pub_detected``: labelled publishers matched, over all labelled
  publishers (those of unmatched nodes count as missed).
- ``pub_named``: labelled publishers matched whose tool ``resolved``
  equals the label's, over **all labelled publishers** (an undetected
  publisher is not named). A label ``resolved: null`` (unknowable) is
  right only when the tool's is null too: a guess is wrong.
- ``labels`` / ``patterns``: matched publishers whose tool ``label`` /
  ``pattern`` equals the label's, over **detected publishers** only.
- ``sub_detected`` / ``sub_named``: as for publishers, over all labelled
  subscriptions.
- ``extra_pubs`` / ``extra_subs``: tool endpoints of matched nodes that
  match no labelled one. A tool ``/tf_static`` subscription of a node whose
  labels list a ``/tf`` subscription is not extra (the labels' convention:
  a tf listener subscribes both, they list ``/tf``).

Per repository, in total, and for C++ / Python and ROS 1 / ROS 2 apart
(by the labelled node's ``language`` and ``ros``). ``--details`` lists
every miss (labelled vs tool value, and location) and a tally of their
kinds. Ends with one line:

RESULT labels nodes=<found>/<n> pub_detected=<pct> (<a>/<b>)
pub_named=<pct> labels=<pct> patterns=<pct> sub_detected=<pct>
sub_named=<pct> extra_pubs=<n>

Usage: python3 bench/labels.py [LABELFILE ...] [--corpus DIR]
  [--workspace LABELFILE=DIR ...] [--build-base NAME] [--reuse]
  [--details] [--json FILE|-] [--self-check]
"""

import argparse
import collections
import json
import os
from pathlib import Path
import posixpath
import re
import subprocess
import sys
import tempfile
import time

from common import colcon
from common import REPO
import yaml

LABELS = REPO / 'bench' / 'labels'
CORPUS = REPO.parent / 'corpus'  # workspaces exported from git snapshots
LINE_SLACK = 2

# label file stem -> corpus workspace (a directory of CORPUS holding src/)
WORKSPACES = {
    'ROBOTIS-GIT__turtlebot3__humble': 'turtlebot3_humble',
    'ROBOTIS-GIT__turtlebot3__noetic': 'turtlebot3_noetic',
    'SteveMacenski__slam_toolbox__humble': 'slam_toolbox_humble',
    'autowarefoundation__autoware.universe__main': 'autoware_universe',
    'cartographer-project__cartographer_ros__master': 'cartographer_ros1',
    'husky__husky__melodic-devel': 'husky_melodic',
    'ros-drivers__rosserial__noetic-devel': 'rosserial',
    'ros-drivers__velodyne__master': 'velodyne_ros1',
    'ros-drivers__velodyne__ros2': 'velodyne_ros2',
    'ros-perception__image_common__humble': 'image_common_humble',
    'ros-perception__image_common__noetic-devel': 'image_common_noetic',
    'ros-perception__perception_pcl__melodic-devel': 'perception_pcl_melodic',
    'ros-simulation__gazebo_ros_pkgs__noetic-devel': 'gazebo_ros_pkgs_noetic',
    'ros-simulation__gazebo_ros_pkgs__ros2': 'gazebo_ros_pkgs_ros2',
    'ros-tooling__topic_tools__humble': 'topic_tools_humble',
    'ros__common_tutorials__noetic-devel': 'common_tutorials',
    'ros__geometry__noetic-devel': 'geometry',
    'ros__nodelet_core__noetic-devel': 'nodelet_core',
    'ros__ros_comm__noetic-devel': 'ros_comm',
}

COUNTS = ('nodes', 'nodes_found', 'pubs', 'pub_detected', 'pub_named',
          'labels_right', 'patterns_right', 'subs', 'sub_detected',
          'sub_named', 'extra_pubs', 'extra_subs')


# ---------------------------------------------------------------- running

def manifest_commit(ws):
    """The commit of a corpus workspace from its MANIFEST.md row, or None."""
    manifest = Path(ws).parent / 'MANIFEST.md'
    try:
        rows = manifest.read_text().splitlines()
    except OSError:
        return None
    for row in rows:
        cells = [c.strip() for c in row.strip().strip('|').split('|')]
        if len(cells) >= 4 and cells[0] == Path(ws).name:
            return cells[3]
    return None


def run_tool(ws, build_base, reuse):
    """(graph dict or None, {node id: summary node}, seconds, problem)."""
    ws = Path(ws)
    base = ws / build_base
    seconds = None
    problem = None
    with tempfile.TemporaryDirectory(prefix='rsia_labels_home_') as home:
        env = dict(os.environ, COLCON_HOME=home)
        if not (reuse and base.is_dir()):
            started = time.monotonic()
            print(f'analysing {ws} ...', file=sys.stderr, flush=True)
            result = subprocess.run(
                [colcon(), 'rsia', 'analyze', '--build-base', build_base],
                cwd=str(ws), env=env, capture_output=True, text=True)
            seconds = time.monotonic() - started
            if result.returncode != 0:
                problem = (f'analyze exited {result.returncode}: '
                           + (result.stderr or result.stdout)[-500:].strip())
        result = subprocess.run(
            [colcon(), 'rsia', 'graph', '--format', 'json',
             '--build-base', build_base],
            cwd=str(ws), env=env, capture_output=True, text=True)
    if result.returncode != 0:
        return None, {}, seconds, (
            f'graph exited {result.returncode}: '
            + (result.stderr or result.stdout)[-500:].strip())
    try:
        graph = json.loads(result.stdout)
    except ValueError as error:
        return None, {}, seconds, f'graph output is not JSON: {error}'
    return graph, summary_nodes(base), seconds, problem


def summary_nodes(base):
    """{node id: node} of every package summary under a build base."""
    nodes = {}
    for path in sorted(Path(base).glob('*/rsia/summary.json')):
        try:
            summary = json.loads(path.read_text(encoding='utf-8'))
        except (OSError, ValueError):
            continue
        for node in summary.get('nodes', []):
            nodes[node.get('id')] = node
    return nodes


# --------------------------------------------------------------- matching

def split_location(location):
    """('normalised/file', line or None) of a ``file:line`` location."""
    if not location:
        return None, None
    file, _, line = str(location).rpartition(':')
    if not file or not line.isdigit():
        return posixpath.normpath(str(location)), None
    return posixpath.normpath(file), int(line)


def last_part(name):
    return re.split(r'::|/', str(name or ''))[-1]


def _strip_py(name):
    name = str(name or '')
    return name[:-3] if name.endswith('.py') else name


def node_rank(label, tool, extra):
    """How well a tool node fits a labelled node: 0 best, None: not at all."""
    if tool.get('package') != label['package']:
        return None
    wanted = str(label['executable'])
    plugin_class = extra.get('plugin_class')
    if wanted in (tool.get('executable'), plugin_class):
        return 0
    parts = {last_part(tool.get('id')), last_part(tool.get('executable')),
             last_part(plugin_class)} - {''}
    if last_part(wanted) in parts:
        return 1
    # a target whose OUTPUT_NAME differs, a google_binary(): the node name
    if last_part(tool.get('name')) == last_part(wanted):
        return 2
    if _strip_py(wanted) == _strip_py(tool.get('executable')):
        return 3
    return None


def endpoint_overlap(label, tool):
    """Labelled endpoints that have a tool endpoint at their location."""
    hits = 0
    for key, tool_key in (('publishers', 'publishers'),
                          ('subscriptions', 'subscribers')):
        places = [split_location(f.get('location'))
                  for f in tool.get(tool_key) or []]
        for fact in label.get(key) or []:
            file, line = split_location(fact.get('location'))
            hits += any(file == tfile and line is not None
                        and tline is not None
                        and abs(line - tline) <= LINE_SLACK
                        for tfile, tline in places)
    return hits


def match_nodes(labelled, tool_nodes, extras):
    """{labelled index: tool node}, one to one.

    Ties (the same rank) go to the tool node with the most labelled
    endpoints at their place, then to the same kind, then to the most
    shared files.
    """
    pairs = []
    for i, label in enumerate(labelled):
        files = {posixpath.normpath(f) for f in label.get('files') or []}
        for j, tool in enumerate(tool_nodes):
            extra = extras.get(tool.get('id'), {})
            rank = node_rank(label, tool, extra)
            if rank is None:
                continue
            shared = len(files & {posixpath.normpath(f)
                                  for f in extra.get('files') or []})
            pairs.append(((rank, -endpoint_overlap(label, tool),
                           tool.get('kind') != label.get('kind'),
                           -shared, i, j), i, j))
    matched, used = {}, set()
    for _, i, j in sorted(pairs):
        if i not in matched and j not in used:
            matched[i] = tool_nodes[j]
            used.add(j)
    return matched


def siblings(tool, tool_nodes, taken):
    """Other tool nodes of the same process: same package, executable, kind.

    One executable that makes several ROS 2 nodes (``pkg/exe/name`` ids) is
    one labelled node; its tool nodes that no labelled node took are
    scored with it.
    """
    return [n for n in tool_nodes
            if n.get('id') not in taken and n is not tool
            and (n.get('package'), n.get('executable'), n.get('kind'))
            == (tool.get('package'), tool.get('executable'),
                tool.get('kind'))]


def written_topic(text):
    """The topic as written in a label: its text before a comment."""
    text = str(text or '').strip()
    return text.split(' (', 1)[0].strip()


def _near(label, fact):
    """How far a tool endpoint's location is from a labelled one.

    Same file: (0, line distance); same file name stem (a declaration in
    the header, the construction in the source): (1, distance); else (2, 0).
    """
    file, line = split_location(label.get('location'))
    tfile, tline = split_location(fact.get('location'))
    distance = (abs(line - tline) if line is not None and tline is not None
                else 0)
    if file and file == tfile:
        return 0, distance
    stem = posixpath.splitext(posixpath.basename(file or ''))[0]
    if stem and stem == posixpath.splitext(
            posixpath.basename(tfile or ''))[0]:
        return 1, distance
    return 2, 0


def _topic_key(fact, tool_side):
    topic = fact.get('topic') if tool_side else written_topic(
        fact.get('topic'))
    return str(topic or '').strip().lstrip('/')


def _disagree(label, fact):
    """0 when a tool endpoint has the labelled one's name, else 1."""
    same_resolved = label.get('resolved') is not None and \
        label.get('resolved') == fact.get('resolved')
    same_topic = bool(_topic_key(label, False)) and \
        _topic_key(label, False) == _topic_key(fact, True)
    return 0 if same_resolved or same_topic else 1


def match_endpoints(labelled, tool):
    """({labelled index: (tool index, how)}, set of unmatched tool indexes).

    By location (same file, line within LINE_SLACK), then by topic as
    written, then by the same non-null resolved name; in each pass the
    closest pairs first (see _near), and of those as close, the pairs that
    agree on the name.
    """
    matched, used = {}, set()
    passes = (
        ('location', lambda label, fact: _near(label, fact)[0] == 0
         and split_location(label.get('location'))[1] is not None
         and split_location(fact.get('location'))[1] is not None
         and _near(label, fact)[1] <= LINE_SLACK),
        ('topic', lambda label, fact: bool(_topic_key(label, False))
         and _topic_key(label, False) == _topic_key(fact, True)),
        ('resolved', lambda label, fact: label.get('resolved') is not None
         and label.get('resolved') == fact.get('resolved')))
    for how, fits in passes:
        # among pairs as close, those that agree on the name first (several
        # endpoints made at one place: a function called once per topic)
        pairs = sorted((_near(label, fact), _disagree(label, fact), i, j)
                       for i, label in enumerate(labelled) if i not in matched
                       for j, fact in enumerate(tool) if j not in used
                       and fits(label, fact))
        for _, _, i, j in pairs:
            if i not in matched and j not in used:
                matched[i] = (j, how)
                used.add(j)
    return matched, set(range(len(tool))) - used


# ---------------------------------------------------------------- scoring

def _short(fact, keys):
    return {k: fact.get(k) for k in keys}


PUB_KEYS = ('topic', 'resolved', 'label', 'pattern', 'location')
SUB_KEYS = ('topic', 'resolved', 'location')
LABEL_PUB_KEYS = PUB_KEYS + ('note',)
LABEL_SUB_KEYS = SUB_KEYS + ('note',)


def score_file(data, graph, extras):
    """(per-node score records, miss records) of one label file."""
    tool_nodes = (graph or {}).get('nodes', [])
    labelled = data.get('nodes') or []
    node_match = match_nodes(labelled, tool_nodes, extras)
    taken = {n.get('id') for n in node_match.values()}
    records, misses = [], []
    for i, label in enumerate(labelled):
        counts = dict.fromkeys(COUNTS, 0)
        counts['nodes'] = 1
        pubs = label.get('publishers') or []
        subs = label.get('subscriptions') or []
        counts['pubs'] = len(pubs)
        counts['subs'] = len(subs)
        who = f'{label["package"]}/{label["executable"]}'
        tool = node_match.get(i)
        record = {'node': who, 'language': label.get('language'),
                  'ros': label.get('ros'), 'tool_node': None,
                  'counts': counts}
        records.append(record)
        if tool is None:
            others = sorted(n.get('id') for n in tool_nodes
                            if n.get('package') == label['package'])
            misses.append({'node': who, 'item': 'node', 'kind': 'node missed',
                           'label': {'kind': label.get('kind')},
                           'tool': {'nodes of the package': others}})
            for pub in pubs:
                misses.append({'node': who, 'item': 'publisher',
                               'kind': 'pub missed (node missed)',
                               'label': _short(pub, LABEL_PUB_KEYS), 'tool': None})
            for sub in subs:
                misses.append({'node': who, 'item': 'subscription',
                               'kind': 'sub missed (node missed)',
                               'label': _short(sub, LABEL_SUB_KEYS), 'tool': None})
            continue
        group = [tool] + siblings(tool, tool_nodes, taken)
        taken.update(n.get('id') for n in group)
        record['tool_node'] = '+'.join(n.get('id') for n in group)
        counts['nodes_found'] = 1
        tool_pubs = [f for n in group for f in n.get('publishers') or []]
        tool_subs = [f for n in group for f in n.get('subscribers') or []]
        found = []
        _score_pubs(who, pubs, tool_pubs, counts, found)
        _score_subs(who, subs, tool_subs, counts, found)
        for miss in found:
            miss['tool_node'] = record['tool_node']
        misses += found
    return records, misses


def _name_kind(want, got):
    if want is None:
        return 'named: tool guessed a name the label says is unknowable'
    if got is None:
        return 'named: tool has no name (null)'
    return 'named: different name'


def _score_pubs(who, pubs, tool_pubs, counts, misses):
    matched, extra = match_endpoints(pubs, tool_pubs)
    for i, pub in enumerate(pubs):
        if i not in matched:
            misses.append({'node': who, 'item': 'publisher',
                           'kind': 'pub missed',
                           'label': _short(pub, LABEL_PUB_KEYS), 'tool': None})
            continue
        fact = tool_pubs[matched[i][0]]
        counts['pub_detected'] += 1
        shown = dict(_short(fact, PUB_KEYS + ('evidence',)),
                     matched_by=matched[i][1])
        if fact.get('resolved') == pub.get('resolved'):
            counts['pub_named'] += 1
        else:
            misses.append({'node': who, 'item': 'publisher',
                           'kind': 'pub ' + _name_kind(pub.get('resolved'),
                                                       fact.get('resolved')),
                           'label': _short(pub, LABEL_PUB_KEYS), 'tool': shown})
        label_right = fact.get('label') == pub.get('label')
        pattern_right = fact.get('pattern') == pub.get('pattern')
        counts['labels_right'] += label_right
        counts['patterns_right'] += pattern_right
        if not (label_right and pattern_right):
            which = 'label' if not label_right else 'pattern'
            misses.append({
                'node': who, 'item': 'publisher',
                'kind': (f'pub {which}: {pub.get("label")}/'
                         f'{pub.get("pattern")} -> tool {fact.get("label")}/'
                         f'{fact.get("pattern")}'),
                'label': _short(pub, LABEL_PUB_KEYS), 'tool': shown})
    for j in sorted(extra):
        counts['extra_pubs'] += 1
        misses.append({'node': who, 'item': 'publisher', 'kind': 'extra pub',
                       'label': None, 'tool': _short(tool_pubs[j], PUB_KEYS)})


def _score_subs(who, subs, tool_subs, counts, misses):
    matched, extra = match_endpoints(subs, tool_subs)
    for i, sub in enumerate(subs):
        if i not in matched:
            misses.append({'node': who, 'item': 'subscription',
                           'kind': 'sub missed',
                           'label': _short(sub, LABEL_SUB_KEYS), 'tool': None})
            continue
        fact = tool_subs[matched[i][0]]
        counts['sub_detected'] += 1
        if fact.get('resolved') == sub.get('resolved'):
            counts['sub_named'] += 1
        else:
            misses.append({
                'node': who, 'item': 'subscription',
                'kind': 'sub ' + _name_kind(sub.get('resolved'),
                                            fact.get('resolved')),
                'label': _short(sub, LABEL_SUB_KEYS),
                'tool': dict(_short(fact, SUB_KEYS),
                             matched_by=matched[i][1])})
    listens_tf = any(s.get('resolved') == '/tf' for s in subs)
    for j in sorted(extra):
        fact = tool_subs[j]
        if listens_tf and fact.get('resolved') == '/tf_static':
            continue  # the labels list a tf listener's /tf only
        counts['extra_subs'] += 1
        misses.append({'node': who, 'item': 'subscription',
                       'kind': 'extra sub', 'label': None,
                       'tool': _short(fact, SUB_KEYS)})


def add(total, counts):
    for key in COUNTS:
        total[key] = total.get(key, 0) + counts.get(key, 0)
    return total


def percent(hit, of):
    return f'{100.0 * hit / of:.1f}' if of else '-'


def summary_fields(c):
    """The RESULT figures of a counts dict (percentages as strings)."""
    return {
        'nodes': f'{c["nodes_found"]}/{c["nodes"]}',
        'pub_detected': percent(c['pub_detected'], c['pubs']),
        'pub_named': percent(c['pub_named'], c['pubs']),
        'labels': percent(c['labels_right'], c['pub_detected']),
        'patterns': percent(c['patterns_right'], c['pub_detected']),
        'sub_detected': percent(c['sub_detected'], c['subs']),
        'sub_named': percent(c['sub_named'], c['subs']),
        'extra_pubs': c['extra_pubs'],
        'extra_subs': c['extra_subs'],
    }


# ---------------------------------------------------------------- output

HEADER = ('{:<44} {:>6} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>5} {:>5}'
          .format('repository', 'nodes', 'pub det', 'named', 'labels',
                  'pattern', 'sub det', 'named', 'x pub', 'x sub'))


def table_row(name, c):
    def frac(hit, of):
        return f'{hit}/{of}'
    return ('{:<44} {:>6} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>5} {:>5}'
            .format(name[:44], frac(c['nodes_found'], c['nodes']),
                    frac(c['pub_detected'], c['pubs']),
                    frac(c['pub_named'], c['pubs']),
                    frac(c['labels_right'], c['pub_detected']),
                    frac(c['patterns_right'], c['pub_detected']),
                    frac(c['sub_detected'], c['subs']),
                    frac(c['sub_named'], c['subs']),
                    c['extra_pubs'], c['extra_subs']))


def percent_row(name, c):
    f = summary_fields(c)
    return ('{:<44} {:>6} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>5} {:>5}'
            .format(name[:44], f['nodes'], f['pub_detected'],
                    f['pub_named'], f['labels'], f['patterns'],
                    f['sub_detected'], f['sub_named'], f['extra_pubs'],
                    f['extra_subs']))


def _value(fact):
    if not fact:
        return '-'
    return ' '.join(f'{k}={v}' for k, v in fact.items()
                    if k != 'evidence' and (v is not None or k == 'resolved'))


def print_details(results):
    tally = collections.Counter()
    example = {}
    print('\nMisses:')
    for repo in results:
        if not repo['misses']:
            continue
        print(f'\n{repo["file"]}:')
        for miss in repo['misses']:
            tally[miss['kind']] += 1
            where = ((miss['label'] or {}).get('location')
                     or (miss['tool'] or {}).get('location'))
            example.setdefault(miss['kind'],
                               f'{repo["file"]} {miss["node"]} {where}')
            node = miss['node']
            if miss.get('tool_node'):
                node += f' (tool {miss["tool_node"]})'
            print(f'  {node}: {miss["kind"]}')
            if miss['label'] is not None:
                print(f'      label: {_value(miss["label"])}')
            if miss['tool'] is not None:
                print(f'      tool:  {_value(miss["tool"])}')
    print('\nKinds of misses (count, kind, first example):')
    for kind, count in tally.most_common():
        print(f'  {count:4d}  {kind}\n        e.g. {example[kind]}')


def score_all(label_files, args, workspaces):
    results = []
    for path in label_files:
        data = yaml.safe_load(Path(path).read_text(encoding='utf-8'))
        stem = Path(path).stem
        ws = workspaces.get(stem)
        entry = {'file': stem, 'repo': data.get('repo'),
                 'branch': data.get('branch'), 'commit': data.get('commit'),
                 'workspace': str(ws) if ws else None, 'notes': [],
                 'seconds': None}
        graph, extras = None, {}
        if ws is None or not (Path(ws) / 'src').is_dir():
            entry['notes'].append(f'no workspace (looked for {ws}); export it '
                                  "with the corpus's export.py")
        else:
            commit = manifest_commit(ws)
            if commit is None:
                entry['notes'].append('workspace commit unknown (no '
                                      'MANIFEST.md row)')
            elif commit != data.get('commit'):
                entry['notes'].append(f'COMMIT MISMATCH: workspace {commit}, '
                                      f'labels {data.get("commit")}')
            graph, extras, entry['seconds'], problem = run_tool(
                ws, args.build_base, args.reuse)
            if problem:
                entry['notes'].append(problem)
        entry['records'], entry['misses'] = score_file(data, graph, extras)
        entry['counts'] = {}
        for record in entry['records']:
            add(entry['counts'], record['counts'])
        results.append(entry)
    return results


def group_totals(results):
    groups = collections.OrderedDict(
        (name, dict.fromkeys(COUNTS, 0))
        for name in ('C++', 'Python', 'ROS 1', 'ROS 2', 'total'))
    for repo in results:
        for record in repo['records']:
            c = record['counts']
            language = {'cpp': 'C++', 'python': 'Python'}.get(
                record['language'])
            if language:
                add(groups[language], c)
            if record['ros'] in (1, 2):
                add(groups[f'ROS {record["ros"]}'], c)
            add(groups['total'], c)
    return groups


def report(results, details):
    print(HEADER)
    for repo in results:
        print(table_row(repo['file'], repo['counts']))
    groups = group_totals(results)
    print()
    for name, c in groups.items():
        print(table_row(name, c))
    print('\npercent (labels, patterns: over detected publishers; all others '
          'over labelled items)')
    print(HEADER)
    for name, c in groups.items():
        print(percent_row(name, c))
    notes = [(r['file'], n) for r in results for n in r['notes']]
    print()
    for file, note in notes:
        print(f'note: {file}: {note}')
    same = sum(1 for r in results if r['workspace'] and not any(
        'COMMIT' in n or 'commit unknown' in n or 'no workspace' in n
        for n in r['notes']))
    print(f'workspace commits: {same} of {len(results)} equal the label '
          "files' commits")
    seconds = [r['seconds'] for r in results if r['seconds'] is not None]
    if seconds:
        print(f'analyze: {len(seconds)} workspaces in {sum(seconds):.0f}s')
    if details:
        print_details(results)
    return groups


def result_line(c):
    f = summary_fields(c)
    return (f'RESULT labels nodes={f["nodes"]} '
            f'pub_detected={f["pub_detected"]} '
            f'({c["pub_detected"]}/{c["pubs"]}) '
            f'pub_named={f["pub_named"]} labels={f["labels"]} '
            f'patterns={f["patterns"]} sub_detected={f["sub_detected"]} '
            f'sub_named={f["sub_named"]} extra_pubs={f["extra_pubs"]}')


# ------------------------------------------------------------- self-check

def self_check():
    """Score a made-up label file against a made-up graph."""
    data = {'nodes': [
        {'package': 'p', 'executable': 'p/Filter', 'kind': 'nodelet',
         'language': 'cpp', 'ros': 1, 'files': ['src/f.cpp'],
         'publishers': [
             {'topic': 'out (private)', 'resolved': None,
              'location': 'src/f.cpp:10', 'label': 'dependent',
              'pattern': 'none'},
             {'topic': 'tf (tf::TransformBroadcaster)', 'resolved': '/tf',
              'location': 'src/f.cpp:40', 'label': 'independent',
              'pattern': 'timer'},
             {'topic': 'tf (a second one)', 'resolved': '/tf',
              'location': 'src/h.cpp:5', 'label': 'dependent',
              'pattern': 'none'}],
         'subscriptions': [
             {'topic': 'in', 'resolved': '/in', 'location': 'src/f.cpp:12'},
             {'topic': 'tf', 'resolved': '/tf', 'location': 'src/f.cpp:3'}]},
        {'package': 'p', 'executable': 'filter_node', 'kind': 'executable',
         'language': 'python', 'ros': 2, 'files': ['p/filter_node.py'],
         'publishers': [{'topic': 'a', 'resolved': '/a',
                         'location': 'p/filter_node.py:5',
                         'label': 'independent', 'pattern': 'timer'},
                        {'topic': 'c', 'resolved': '/c',
                         'location': 'p/helper.py:3',
                         'label': 'independent', 'pattern': 'timer'}],
         'subscriptions': []},
        {'package': 'q', 'executable': 'lost', 'kind': 'executable',
         'language': 'cpp', 'ros': 1, 'files': [],
         'publishers': [{'topic': 'b', 'resolved': '/b', 'location': 'x:1',
                         'label': 'dependent', 'pattern': 'none'}],
         'subscriptions': []}]}
    graph = {'nodes': [
        {'id': 'p/filter_node', 'package': 'p', 'executable': 'filter_node',
         'kind': 'executable',
         'publishers': [{'topic': 'a', 'resolved': '/a', 'label': 'dependent',
                         'pattern': 'none', 'location': 'p/filter_node.py:6'}],
         'subscribers': []},
        {'id': 'p/filter_node/helper', 'package': 'p',
         'executable': 'filter_node', 'kind': 'executable',
         'publishers': [{'topic': 'c', 'resolved': '/c',
                         'label': 'independent', 'pattern': 'timer',
                         'location': 'p/helper.py:3'}],
         'subscribers': []},
        {'id': 'p/Filter', 'package': 'p', 'executable': 'Filter',
         'kind': 'nodelet',
         'publishers': [
             {'topic': 'out', 'resolved': '/out', 'label': 'dependent',
              'pattern': 'none', 'location': 'src/f.cpp:11'},
             {'topic': '/tf', 'resolved': '/tf', 'label': 'dependent',
              'pattern': 'none', 'location': 'include/p/h.hpp:3'},
             {'topic': '/tf', 'resolved': '/tf', 'label': 'independent',
              'pattern': 'timer', 'location': 'include/p/f.hpp:7'},
             {'topic': 'debug', 'resolved': '/debug', 'label': 'dependent',
              'pattern': 'none', 'location': 'src/f.cpp:99'}],
         'subscribers': [
             {'topic': 'in', 'resolved': '/in', 'location': 'src/f.cpp:14'},
             {'topic': '/tf', 'resolved': '/tf', 'location': 'src/f.cpp:3'},
             {'topic': '/tf_static', 'resolved': '/tf_static',
              'location': 'src/f.cpp:3'}]}]}
    extras = {'p/Filter': {'plugin_class': 'p::Filter',
                           'files': ['src/f.cpp']}}
    records, misses = score_file(data, graph, extras)
    total = {}
    for record in records:
        add(total, record['counts'])
    expected = {'nodes': 3, 'nodes_found': 2, 'pubs': 6, 'pub_detected': 5,
                'pub_named': 4, 'labels_right': 4, 'patterns_right': 4,
                'subs': 2, 'sub_detected': 2, 'sub_named': 2,
                'extra_pubs': 1, 'extra_subs': 0}
    assert total == expected, (total, expected)
    assert [r['tool_node'] for r in records] == [
        'p/Filter', 'p/filter_node+p/filter_node/helper', None], records
    kinds = sorted(m['kind'] for m in misses)
    assert kinds == [
        'extra pub', 'node missed', 'pub label: independent/timer -> tool '
        'dependent/none', 'pub missed (node missed)',
        'pub named: tool guessed a name the label says is unknowable'], kinds
    # one tool node is never given to two labelled nodes
    twin = dict(data['nodes'][1], executable='filter_node.py')
    assert len(match_nodes([data['nodes'][1], twin], graph['nodes'][:1],
                           {})) == 1
    assert summary_fields(total)['pub_named'] == '66.7'
    print('self-check ok')


# ------------------------------------------------------------------- main

def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('label_files', nargs='*',
                        help='label files (default: all of bench/labels)')
    parser.add_argument('--corpus', default=str(CORPUS),
                        help='where the WORKSPACES table points')
    parser.add_argument('--workspace', action='append', default=[],
                        metavar='LABELFILE=DIR',
                        help='the workspace root of a label file (its stem)')
    parser.add_argument('--build-base', default='build_labels',
                        help='relative to the workspace root')
    parser.add_argument('--reuse', action='store_true',
                        help='skip analyze where the build base exists')
    parser.add_argument('--details', action='store_true',
                        help='list every miss and a tally of their kinds')
    parser.add_argument('--json', metavar='FILE',
                        help="write the scores and misses as JSON ('-': "
                             'stdout, instead of the table)')
    parser.add_argument('--self-check', action='store_true',
                        help='check the matching and scoring on made-up '
                             'data, run nothing')
    args = parser.parse_args(argv)
    if args.self_check:
        self_check()
        return
    workspaces = {stem: Path(args.corpus) / name
                  for stem, name in WORKSPACES.items()}
    for option in args.workspace:
        stem, sep, directory = option.partition('=')
        if not sep:
            parser.error(f'--workspace {option}: not LABELFILE=DIR')
        workspaces[Path(stem).stem] = Path(directory).resolve()
    files = args.label_files or sorted(str(p) for p in LABELS.glob('*.yaml'))
    results = score_all(files, args, workspaces)
    if args.json == '-':
        groups = group_totals(results)
    else:
        groups = report(results, args.details)
    if args.json:
        document = {
            'schema': 'colcon-rsia-bench/labels@1',
            'result': summary_fields(groups['total']),
            'groups': groups,
            'repositories': [{k: v for k, v in r.items()} for r in results]}
        text = json.dumps(document, indent=1, sort_keys=True)
        if args.json == '-':
            print(text)
        else:
            Path(args.json).write_text(text + '\n', encoding='utf-8')
    if args.json != '-':
        print(result_line(groups['total']))


if __name__ == '__main__':
    main()
