# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Predicted publishing rates of every topic, and what-if questions.

A topic's rate comes from its publishers: an independent publisher's own
timer or Rate loop (a literal or a constant), a dependent publisher's
triggers (one trigger: it follows that topic; a synchronizer: its slowest
input; several triggers: at most their sum; every n-th message: the
trigger's rate / n). Anything else is ``unknown``: never a guess. Several
publishers on one topic add up (an upper bound).
"""

from dataclasses import dataclass
from dataclasses import field
from typing import List
from typing import Optional

from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.kinds import PATTERN_RATE_LOOP
from colcon_rsia.summary.kinds import PATTERN_TIMER
from colcon_rsia.system.graph import ALL_INPUTS
from colcon_rsia.system.impact import crosses
from colcon_rsia.system.impact import PAPER

RATES_SCHEMA = 'colcon-rsia/rates@1'
UNKNOWN = 'unknown'
SET = 'set'


@dataclass
class Rate:
    """A topic's (or a publisher's) predicted rate and where it comes from."""

    hz: Optional[float]
    source: str
    chain: List[str] = field(default_factory=list)
    # it follows a changed node: its rate may change to anything
    changed: bool = False


def _fmt(hz):
    return f'{hz:g} Hz' if hz is not None else UNKNOWN


def _unknown(why, changed=False):
    return Rate(None, UNKNOWN, [why], changed)


class _Predictor:

    def __init__(self, system, set_rates, changed):
        self.system = system
        self.set_rates = dict(set_rates or {})
        self.changed = set(changed or ())
        self.rates = {}
        self.in_progress = set()

    def topic(self, name):
        if name in self.rates:
            return self.rates[name]
        if name in self.in_progress:
            return _unknown(f'{name} follows itself (a cycle)')
        # the topics it follows first, the farthest first, without
        # recursion: a chain of a thousand nodes is deeper than Python's
        # stack. Each is then computed from rates already known (or in
        # progress: a cycle), as if followed recursively.
        self.in_progress.add(name)
        stack = [(name, iter(self._inputs(name)))]
        while stack:
            current, inputs = stack[-1]
            for following in inputs:
                if following not in self.rates and \
                        following not in self.in_progress:
                    self.in_progress.add(following)
                    stack.append((following, iter(self._inputs(following))))
                    break
            else:
                stack.pop()
                self.rates[current] = self._topic(current)
                self.in_progress.discard(current)
        return self.rates[name]

    def _inputs(self, name):
        """The topics the rate of topic `name` may follow."""
        if name in self.set_rates:
            return []
        vertex = ('topic', name)
        if vertex not in self.system.graph:
            return []
        inputs = []
        for node in sorted(self.system.graph.predecessors(vertex)):
            instance = self.system.instances[node[1]]
            if node[1] in self.changed or instance.node is None:
                continue
            for entry in instance.publishers:
                if entry['resolved'] == name and \
                        entry['publisher'].label != INDEPENDENT:
                    inputs += [trigger for trigger, _ in entry['triggers']
                               if trigger != ALL_INPUTS and ':' not in trigger]
        return inputs

    def _topic(self, name):
        if name in self.set_rates:
            return Rate(self.set_rates[name], SET,
                        [f'{name}: {_fmt(self.set_rates[name])} (--set-rate)'])
        graph = self.system.graph
        vertex = ('topic', name)
        publishers = sorted(graph.predecessors(vertex)) \
            if vertex in graph else []
        rates = []
        for node in publishers:
            instance = self.system.instances[node[1]]
            if node[1] in self.changed:
                rates.append(_unknown(
                    f'{name}: published by the changed node {node[1]}',
                    changed=True))
            elif instance.node is None:
                rates.append(_unknown(
                    f'{name}: published by {node[1]}, not analysed'))
            else:
                rates += [self._publisher(instance, entry)
                          for entry in instance.publishers
                          if entry['resolved'] == name]
        if not rates:
            return _unknown(f'{name}: no publisher in the system')
        if len(rates) == 1:
            return rates[0]
        return _combine(
            'sum of', rates, sum, f'{name}: {len(rates)} publishers')

    def _publisher(self, instance, entry):
        publisher = entry['publisher']
        where = f'{instance.id} {publisher.location}'
        if publisher.label == INDEPENDENT:
            hz = publisher.rate_hz or publisher.paced_rate_hz
            pattern = publisher.paced_by or publisher.pattern
            if hz is None or pattern not in _PACED_SOURCES:
                return _unknown(
                    f'{entry["resolved"]}: independent ({publisher.pattern}) '
                    f'but not at one constant rate ({where})')
            source = _PACED_SOURCES[pattern]
            return Rate(hz, source,
                        [f'{entry["resolved"]}: {_fmt(hz)} {source} '
                         f'({where})'])
        parts = []
        groups = {}
        for name, trigger in entry['triggers']:
            if name == ALL_INPUTS:
                why = trigger.detail if trigger else 'no triggers recorded'
                return _unknown(
                    f'{entry["resolved"]}: every input drives it: {why} '
                    f'({where})')
            if ':' in name:
                return _unknown(
                    f'{entry["resolved"]}: driven by {name} ({where})')
            if trigger.sync:
                groups.setdefault(trigger.sync, []).append(name)
                continue
            rate = self.topic(name)
            if trigger.every and rate.hz is not None:
                rate = Rate(
                    rate.hz / trigger.every, f'{name} / {trigger.every}',
                    rate.chain + [f'{entry["resolved"]}: every '
                                  f'{trigger.every}th message of {name} '
                                  f'({where})'], rate.changed)
            elif trigger.every:
                rate = Rate(None, UNKNOWN, rate.chain, rate.changed)
            else:
                rate = Rate(rate.hz, f'follows {name}', rate.chain + [
                    f'{entry["resolved"]}: follows {name} ({where})'],
                    rate.changed)
            parts.append(rate)
        for sync, names in sorted(groups.items()):
            inputs = [self.topic(name) for name in sorted(set(names))]
            parts.append(_combine(
                'slowest of', inputs, min,
                f'{entry["resolved"]}: synchronizer at {sync} of '
                f"{', '.join(sorted(set(names)))} ({where})",
                sorted(set(names))))
        if not parts:
            return _unknown(f'{entry["resolved"]}: no trigger ({where})')
        if len(parts) == 1:
            return parts[0]
        return _combine('sum of', parts, sum,
                        f'{entry["resolved"]}: at most the sum of its '
                        f'triggers ({where})')


# the pattern of an independent publisher -> the source of its rate
_PACED_SOURCES = {
    PATTERN_TIMER: 'timer',
    PATTERN_RATE_LOOP: 'Rate loop',
}


def _combine(how, rates, function, why, names=None):
    chain = [line for rate in rates for line in rate.chain] + [why]
    changed = any(rate.changed for rate in rates)
    if any(rate.hz is None for rate in rates):
        return Rate(None, UNKNOWN, chain, changed)
    what = ', '.join(names) if names else ', '.join(
        rate.source[len('follows '):] if rate.source.startswith('follows ')
        else rate.source for rate in rates)
    return Rate(function(rate.hz for rate in rates), f'{how} {what}', chain,
                changed)


def predict_rates(system, *, set_rates=None, changed=()):
    """{topic: :class:`Rate`} for every topic of the system.

    :param set_rates: {topic: Hz} the what-if question sets
    :param changed: instance ids of changed nodes: their topics' rates
      may change to anything (``unknown``, marked changed)
    """
    predictor = _Predictor(system, set_rates, changed)
    return {name: predictor.topic(name) for name in system.topics()}


def what_if(system, *, set_rates=None, changed=(), model_name=PAPER):
    """The topics whose rate changes and those an edge keeps unchanged.

    :returns: (changes [{topic, from, to, source}], kept [{topic, hz,
      node, via, edge}])
    """
    before = predict_rates(system)
    after = predict_rates(system, set_rates=set_rates, changed=changed)
    changes = []
    moved = set()
    for name in sorted(after):
        old, new = before[name], after[name]
        if new.hz != old.hz or new.changed or new.source == SET:
            moved.add(name)
            changes.append({
                'topic': name, 'from': old.hz, 'to': new.hz,
                'may_change': new.changed, 'source': new.source})
    kept = []
    graph = system.graph
    for name in sorted(moved):
        for node in sorted(graph.successors(('topic', name))):
            if node[1] in changed:
                continue
            for out in sorted(graph.successors(node)):
                data = graph.edges[node, out]
                if out[1] in moved or crosses(data, name, model_name):
                    continue
                why = 'independent' if data['label'] == INDEPENDENT \
                    else f'not triggered by {name}'
                kept.append({
                    'topic': out[1], 'hz': after[out[1]].hz,
                    'node': node[1], 'via': name,
                    'edge': f'{node[1]} -> {out[1]} ({why})'})
    return changes, kept


def rates_to_json(system, *, set_rates=None, changed=(), model_name=PAPER):
    """The rates@1 contract (see docs/triggers-and-rates.md)."""
    rates = predict_rates(system, set_rates=set_rates, changed=changed)
    result = {
        'schema': RATES_SCHEMA,
        'model': model_name,
        'set_rates': dict(sorted((set_rates or {}).items())),
        'changed': sorted(changed),
        'topics': [{
            'name': name, 'hz': rate.hz, 'source': rate.source,
            'chain': rate.chain} for name, rate in sorted(rates.items())],
    }
    if set_rates or changed:
        result['changes'], result['kept'] = what_if(
            system, set_rates=set_rates, changed=changed,
            model_name=model_name)
    return result
