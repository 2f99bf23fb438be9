# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Generated systems of any size, written as analysis summaries.

Nothing is compiled: the package summaries are written directly into
``BUILD_BASE/<package>/rsia/summary.json``, the store the subverbs read.
The system looks like a robot's: node ``i`` belongs to the stage
``i * STAGES // n`` of a pipeline (sensor drivers first, then filters,
fusion, planning, control, actuator drivers), packages hold eight
consecutive nodes, and every node reads one to three topics of the nodes
at about the same place in the previous stage. Sensor drivers and one node in four publish
from a timer (independent); the others publish from their subscription
callbacks (dependent). Every fourth node publishes ``/tf`` and every sixth
reads it, so ``/tf`` is a hub; the actuator drivers publish odometry the
planners read (cycles). The same size gives the same system.
"""

import random

from colcon_rsia import __version__
from colcon_rsia.summary.kinds import DEPENDENT
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.kinds import PATTERN_NONE
from colcon_rsia.summary.kinds import PATTERN_TIMER
from colcon_rsia.summary.nodes import Evidence
from colcon_rsia.summary.nodes import LabelledPublisher
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.nodes import NodeSubscriber
from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.store import write_summary

STAGES = ('sensor', 'filter', 'fusion', 'planning', 'control', 'driver')
NODES_PER_PACKAGE = 8
HUB_TOPIC = '/tf'
PUBLISHES_TF_EVERY = 4
READS_TF_EVERY = 6
WINDOW = 6  # how far a node looks around its place in the previous stage


def stage_of(index, count):
    """The pipeline stage of node `index` of `count`."""
    return STAGES[index * len(STAGES) // count]


def node_id(index):
    """``pkg_<package>/<stage>_<index>``."""
    return f'pkg_{index // NODES_PER_PACKAGE:03d}/node_{index:04d}'


def changed_node(count):
    """A sensor driver in the middle with the most readers of its topic."""
    readers = {}
    for summary in synthetic_summaries(count):
        for node in summary.nodes:
            for subscriber in node.subscribers:
                readers[subscriber.topic] = readers.get(subscriber.topic, 0) + 1
    sensors = [i for i in range(count) if stage_of(i, count) == 'sensor']
    middle = sensors[len(sensors) // 4:len(sensors) * 3 // 4] or sensors
    return node_id(max(
        middle, key=lambda i: (readers.get(f'/topic_{i:04d}', 0), -i)))


def _publisher(topic, index, line, *, timer):
    location = f'src/node_{index:04d}.cpp:{line}'
    if timer:
        evidence = [Evidence('timer', f'src/node_{index:04d}.cpp:'
                             f'{line + 20}', '10 Hz')]
        label, pattern, rate = INDEPENDENT, PATTERN_TIMER, 10.0
    else:
        evidence = [Evidence(
            'subscriber', f'src/node_{index:04d}.cpp:{line + 30}',
            'published from a subscription callback')]
        label, pattern, rate = DEPENDENT, PATTERN_NONE, None
    return LabelledPublisher(
        topic=topic, topic_is_literal=True, msg_type='std_msgs/String',
        api='ros::NodeHandle::advertise', handle=f'pub_{line}',
        namespace='', location=location, label=label, pattern=pattern,
        rate_hz=rate, publish_sites=[location], evidence=evidence)


def _subscriber(topic, index, line):
    return NodeSubscriber(
        topic=topic, topic_is_literal=True, msg_type='std_msgs/String',
        api='ros::NodeHandle::subscribe', callback=f'on_message_{line}',
        namespace='', location=f'src/node_{index:04d}.cpp:{line}')


def synthetic_summaries(count, seed=20):
    """The package summaries of a generated system of `count` nodes."""
    rng = random.Random(seed * 100003 + count)
    stages = [stage_of(i, count) for i in range(count)]
    bounds = {}  # stage: (first index, last index + 1)
    for index, stage in enumerate(stages):
        bounds[stage] = (bounds.get(stage, (index,))[0], index + 1)
    packages = {}
    for index in range(count):
        stage = stages[index]
        identifier = node_id(index)
        package, executable = identifier.split('/')
        timer = stage == 'sensor' or index % 4 == 0
        publishers = [_publisher(f'/topic_{index:04d}', index, 40,
                                 timer=timer)]
        subscribers = []
        if stage != 'sensor':
            # from the previous stage, near the same relative position
            previous = STAGES[STAGES.index(stage) - 1]
            begin, end = bounds[previous]
            mine = bounds[stage]
            share = (index - mine[0]) / max(1, mine[1] - mine[0])
            centre = begin + int(share * (end - begin))
            window = list(range(max(begin, centre - WINDOW),
                                min(end, centre + WINDOW + 1)))
            for source in sorted(set(rng.sample(
                    window, min(len(window), rng.randint(1, 3))))):
                subscribers.append(
                    _subscriber(f'/topic_{source:04d}', index, 60 + source % 9))
        if stage == 'driver':
            publishers.append(_publisher(
                f'/odom_{index:04d}', index, 80, timer=True))
        if stage == 'planning':
            drivers = [i for i in range(count) if stages[i] == 'driver']
            if drivers:
                source = drivers[index % len(drivers)]
                subscribers.append(
                    _subscriber(f'/odom_{source:04d}', index, 90))
        if index % PUBLISHES_TF_EVERY == 1:
            publishers.append(_publisher(HUB_TOPIC, index, 100, timer=True))
        if index % READS_TF_EVERY == 5:
            subscribers.append(_subscriber(HUB_TOPIC, index, 110))
        node = Node(
            id=identifier, package=package, executable=executable,
            kind='executable', name=executable,
            sources=[f'src/{executable}.cpp'],
            files=[f'src/{executable}.cpp'],
            publishers=publishers, subscribers=subscribers)
        packages.setdefault(package, []).append(node)
    return [
        PackageSummary(
            package=name, path=f'/generated/src/{name}',
            tool_version=__version__, nodes=nodes)
        for name, nodes in sorted(packages.items())]


def write_synthetic_workspace(build_base, count):
    """Write the summaries under `build_base`; return the changed node."""
    for summary in synthetic_summaries(count):
        write_summary(str(build_base / summary.package), summary)
    return changed_node(count)
