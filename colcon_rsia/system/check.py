# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The static model against recordings: ``colcon rsia check --bag``.

One bag: every topic's measured rate against its predicted rate
(:mod:`colcon_rsia.system.rates`). Two bags, before and after a change:
the topics whose measured rate changed against those the rate impact of
the changed nodes predicts may change. A topic that changed unpredicted is
a soundness miss of the model; it is listed with the edges that were
supposed to keep its rate.
"""

from colcon_rsia.system.impact import PAPER
from colcon_rsia.system.rates import predict_rates
from colcon_rsia.system.rates import what_if

CHECK_SCHEMA = 'colcon-rsia/check@1'
DEFAULT_TOLERANCE = 0.15

# one bag
OK = 'ok'
MISMATCH = 'mismatch'
UNPREDICTED = 'unpredicted'
NOT_RECORDED = 'not recorded'
# two bags
CHANGED = 'changed'
UNCHANGED = 'unchanged'


def within(measured, reference, tolerance):
    """Whether a measured rate is within a relative tolerance of another."""
    return abs(measured - reference) <= tolerance * abs(reference)


def check_one(system, measured, *, tolerance=DEFAULT_TOLERANCE):
    """The check@1 result of one bag.

    :param measured: {topic: :class:`colcon_rsia.system.bags.TopicRecording`}
    """
    predicted = predict_rates(system)
    topics = []
    for name in sorted(set(predicted) | set(measured)):
        rate = predicted.get(name)
        recording = measured.get(name)
        predicted_hz = rate.hz if rate is not None else None
        hz = recording.hz if recording is not None else None
        if hz is None:
            status = NOT_RECORDED
        elif predicted_hz is None:
            status = UNPREDICTED
        elif within(hz, predicted_hz, tolerance):
            status = OK
        else:
            status = MISMATCH
        topics.append({
            'name': name, 'before_hz': _round(hz), 'after_hz': None,
            'predicted_hz': predicted_hz, 'status': status,
            'messages': recording.count if recording is not None else 0,
            'prediction': rate.chain if rate is not None else [
                'the topic is in no analysed node (not in the model)']})
    return _result(topics, tolerance, changed=None)


def check_two(system, before, after, changed, *,
              tolerance=DEFAULT_TOLERANCE, model_name=PAPER):
    """The check@1 result of two bags around a change of `changed`.

    A topic changed when both bags measure it and the rates differ by
    more than the tolerance, or when only one bag has it. A change of a
    topic no analysed node publishes (``/rosout``, which every node's client
    library feeds with its log lines) says nothing about the model's edges:
    it is listed apart, never as unexpected.
    """
    predicted = predict_rates(system)
    changes, kept = what_if(system, changed=changed, model_name=model_name)
    may_change = {c['topic'] for c in changes}
    topics = []
    unexpected = []
    outside = []
    unchanged_predicted = []
    for name in sorted(set(before) | set(after) | set(predicted)):
        old = before[name].hz if name in before else None
        new = after[name].hz if name in after else None
        if old is None and new is None:
            status = NOT_RECORDED
        elif old is None or new is None or not within(new, old, tolerance):
            status = CHANGED
        else:
            status = UNCHANGED
        rate = predicted.get(name)
        topics.append({
            'name': name, 'before_hz': _round(old), 'after_hz': _round(new),
            'predicted_hz': rate.hz if rate is not None else None,
            'status': status, 'predicted_to_change': name in may_change})
        if status == CHANGED and rate is None:
            outside.append({'topic': name, 'before_hz': _round(old),
                            'after_hz': _round(new)})
        elif status == CHANGED and name not in may_change:
            unexpected.append({
                'topic': name, 'before_hz': _round(old),
                'after_hz': _round(new),
                'kept_by': [k['edge'] for k in kept if k['topic'] == name]})
        elif status == UNCHANGED and name in may_change:
            unchanged_predicted.append({
                'topic': name, 'before_hz': _round(old),
                'after_hz': _round(new)})
    result = _result(topics, tolerance, changed=sorted(changed))
    result['model'] = model_name
    result['unexpected_changes'] = unexpected
    result['changes_outside_the_model'] = outside
    result['predicted_but_unchanged'] = unchanged_predicted
    return result


def _round(hz):
    return round(hz, 3) if hz is not None else None


def _result(topics, tolerance, changed):
    counts = {}
    for topic in topics:
        counts[topic['status']] = counts.get(topic['status'], 0) + 1
    return {
        'schema': CHECK_SCHEMA, 'tolerance': tolerance,
        'changed': changed, 'topics': topics,
        'counts': dict(sorted(counts.items())),
        'unexpected_changes': [], 'changes_outside_the_model': [],
        'predicted_but_unchanged': []}
