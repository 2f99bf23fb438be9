# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Project a summary onto the fields of the hand-written expected files."""

import json
from pathlib import Path
import re

PUBLISHER_FIELDS = ('topic', 'msg_type', 'api', 'label', 'pattern', 'rate_hz')
SUBSCRIBER_FIELDS = ('topic', 'msg_type', 'api', 'callback')
TIMER_FIELDS = ('api', 'callback', 'rate_hz')
SERVICE_FIELDS = ('name', 'api', 'callback')
ACTION_FIELDS = ('name', 'api', 'role')
CLIENT_FIELDS = ('name', 'api')
SECTIONS = {
    'publishers': PUBLISHER_FIELDS,
    'subscribers': SUBSCRIBER_FIELDS,
    'timers': TIMER_FIELDS,
    'services': SERVICE_FIELDS,
    'actions': ACTION_FIELDS,
    'clients': CLIENT_FIELDS,
}
# what the newer expected files (ros2) also state: the node name and
# namespace the code gives, and the parameter a topic name comes from
NAMED_NODE_FIELDS = ('name', 'namespace')
TOPIC_PARAM_SECTIONS = ('publishers', 'subscribers')


def _normal(value):
    # YAML writes 10 and 10.0 alike for a person; compare numbers as floats
    if isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    return value


def _topic_param(item):
    param = item.get('topic_param')
    return None if not param else {
        'name': param['name'], 'default': param.get('default')}


def _entries(items, names, with_topic_param=False):
    projected = []
    for item in items:
        entry = {name: _normal(item.get(name)) for name in names}
        if with_topic_param:
            entry['topic_param'] = _topic_param(item)
        projected.append(entry)
    return sorted(projected, key=lambda e: json.dumps(e, sort_keys=True))


def project_node(node, named=False):
    """The comparable view of one node (summary or expected file).

    :param named: also compare the node's name and namespace and the
      parameters topic names come from
    """
    view = {'id': node['id'], 'kind': node.get('kind', 'executable')}
    if view['kind'] == 'plugin':
        view['base_class'] = node.get('base_class')
        view['host'] = node.get('host')
    if named:
        for name in NAMED_NODE_FIELDS:
            view[name] = node.get(name)
    for section, names in SECTIONS.items():
        view[section] = _entries(
            node.get(section) or [], names,
            with_topic_param=named and section in TOPIC_PARAM_SECTIONS)
    return view


def project_nodes(nodes, named=False):
    """{node id: view} of a list of nodes."""
    return {node['id']: project_node(node, named) for node in nodes}


def _source_line(package_path, location):
    file, _, line = location.rpartition(':')
    lines = (Path(package_path) / file).read_text().splitlines()
    return lines[int(line) - 1]


def check_evidence(summary, publish_words):
    """Assert every label's evidence points at the code that decided it.

    :returns: the number of publish sites checked
    """
    checked = 0
    for node in summary['nodes']:
        for publisher in node['publishers']:
            assert publisher['evidence'], publisher
            for site in publisher['publish_sites']:
                text = _source_line(summary['path'], site)
                # a workspace wrapper that publishes: the call names it
                wrappers = {e['detail'].split('::')[-1]
                            for e in publisher['evidence']
                            if e['kind'] == 'publish_site' and
                            e['location'] == site}
                assert publish_words.search(text) or any(
                    re.search(rf'\b{w}\s*[<(]', text) for w in wrappers), \
                    (site, text)
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
    return checked
