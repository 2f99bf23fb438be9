# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The system graph as the graph@1 document, Graphviz DOT or a listing."""

from colcon_rsia.render import DOT
from colcon_rsia.render import JSON
from colcon_rsia.render import json_text
from colcon_rsia.render import TEXT
from colcon_rsia.safe_files import printable
from colcon_rsia.safe_files import printable_lines
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.system.graph import ALL_INPUTS

GRAPH_SCHEMA = 'colcon-rsia/graph@1'
# the graph alone can be drawn
FORMATS = (TEXT, JSON, DOT)


def render_graph(system, fmt):
    """The :class:`colcon_rsia.system.graph.SystemGraph` in format `fmt`."""
    if fmt == JSON:
        return json_text(graph_to_json(system))
    if fmt == DOT:
        return graph_to_dot(system)
    return graph_to_text(system)


def graph_to_json(system):
    """The graph@1 contract (see docs/json.md)."""
    nodes = []
    for instance in sorted(system.instances.values(), key=lambda i: i.id):
        node = instance.node
        nodes.append({
            'id': instance.id,
            'name': instance.fqn,
            'package': instance.package,
            'executable': instance.executable,
            'kind': instance.kind,
            **({'note': instance.note} if instance.note else {}),
            'publishers': [{
                'topic': p['publisher'].topic,
                'resolved': p['resolved'],
                'msg_type': p['publisher'].msg_type,
                'label': p['publisher'].label,
                'pattern': p['publisher'].pattern,
                'rate_hz': p['publisher'].rate_hz,
                'api': p['publisher'].api,
                'location': p['publisher'].location,
                'evidence': [
                    {'kind': e.kind, 'location': e.location,
                     'detail': e.detail}
                    for e in p['publisher'].evidence],
                **_triggers_json(p),
            } for p in instance.publishers],
            'subscribers': [{
                'topic': s['subscriber'].topic,
                'resolved': s['resolved'],
                'msg_type': s['subscriber'].msg_type,
                'callback': s['subscriber'].callback,
                'api': s['subscriber'].api,
                'location': s['subscriber'].location,
            } for s in instance.subscribers],
            'services': [{
                'name': s.name, 'api': s.api, 'callback': s.callback,
                'location': s.location}
                for s in (node.services if node else [])],
            'actions': [{
                'name': a.name, 'api': a.api, 'role': a.role,
                'callbacks': a.callbacks, 'location': a.location}
                for a in (node.actions if node else [])],
            'clients': [{
                'name': c.name, 'api': c.api, 'location': c.location}
                for c in (node.clients if node else [])],
        })
    topics = []
    for name in system.topics():
        vertex = ('topic', name)
        topics.append({
            'name': name,
            'publishers': sorted(
                v[1] for v in system.graph.predecessors(vertex)),
            'subscribers': sorted(
                v[1] for v in system.graph.successors(vertex)),
        })
    return {'schema': GRAPH_SCHEMA, 'nodes': nodes, 'topics': topics}


def _triggers_json(entry):
    """The optional ``triggers`` of a dependent publisher in graph@1."""
    if entry['publisher'].label == INDEPENDENT:
        return {}
    return {
        'triggers': sorted({name for name, _ in entry['triggers']}),
        'trigger_evidence': [{
            'trigger': name,
            'location': trigger.location if trigger else None,
            'detail': trigger.detail if trigger else
            'the summary records no triggers: re-analyse the package',
            'every': trigger.every if trigger else None,
            'sync': trigger.sync if trigger else None,
        } for name, trigger in entry['triggers']],
    }


def graph_to_dot(system, *, changed=(), rate_impact=(), traditional=(),
                 rates=None):
    """Graphviz DOT: nodes as ellipses, topics as boxes, independent dashed.

    :param rates: {topic: :class:`colcon_rsia.system.rates.Rate`}: each topic's
      label shows its predicted rate and where it comes from
    """
    def quote(text):
        # a line break stays DOT's own \n escape; the rest of a name is
        # printable (the DOT text goes to the console too)
        return '"' + '\\n'.join(
            printable(line).replace('\\', '\\\\').replace('"', '\\"')
            for line in text.split('\n')) + '"'
    lines = ['digraph rsia {', '  rankdir=LR;',
             '  node [fontname="Helvetica", fontsize=10];']
    for instance in sorted(system.instances.values(), key=lambda i: i.id):
        style = 'filled'
        color = 'white'
        if instance.id in changed:
            color = '#f4a261'
        elif instance.id in rate_impact:
            color = '#e76f51'
        elif instance.id in traditional:
            color = '#e9c46a'
        lines.append(
            f'  {quote("node:" + instance.id)} [label={quote(instance.id)}, '
            f'shape=ellipse, style={style}, fillcolor="{color}"];')
    for name in system.topics():
        label = name
        rate = (rates or {}).get(name)
        if rate is not None:
            hz = f'{rate.hz:g} Hz' if rate.hz is not None else 'unknown'
            label += f'\n{hz}' + (
                f' ({rate.source})' if rate.hz is not None else '')
        lines.append(
            f'  {quote("topic:" + name)} [label={quote(label)}, shape=box];')
    for source, target, data in sorted(system.graph.edges(data=True)):
        attributes = ''
        if source[0] == 'node':
            if data['label'] == INDEPENDENT:
                attributes = ' [style=dashed, label="independent"]'
            elif ALL_INPUTS not in data.get('triggers', {ALL_INPUTS}):
                triggers = ', '.join(sorted(data['triggers']))
                attributes = f' [label={quote("triggered by " + triggers)}]'
        lines.append(
            f'  {quote(source[0] + ":" + source[1])} -> '
            f'{quote(target[0] + ":" + target[1])}{attributes};')
    lines.append('}')
    return '\n'.join(lines) + '\n'


def _unresolved(endpoint):
    """How an endpoint whose global name is unknown shows its topic."""
    if endpoint.topic is None:
        return '(topic unknown)'
    return f'{endpoint.topic} (not resolved)'


def graph_to_text(system):
    """A readable listing of nodes, their edges and labels."""
    lines = []
    for instance in sorted(system.instances.values(), key=lambda i: i.id):
        lines.append(f'{instance.id} ({instance.kind}, {instance.fqn})')
        if instance.node is None:
            lines.append('  (package not analysed: assumed to read and '
                         'write its remapped topics)')
        elif instance.note:
            lines.append(f'  ({instance.note})')
        for p in instance.publishers:
            publisher = p['publisher']
            rate = f' {publisher.rate_hz:g} Hz' if publisher.rate_hz else ''
            lines.append(
                f'  publishes {p["resolved"] or _unresolved(publisher)}'
                f' [{publisher.label}: {publisher.pattern}{rate}]'
                f' {publisher.location}')
        for s in instance.subscribers:
            subscriber = s['subscriber']
            callback = subscriber.callback or '(callback unknown)'
            lines.append(
                f'  subscribes {s["resolved"] or _unresolved(subscriber)}'
                f' -> {callback} {subscriber.location}')
    return printable_lines(lines)
