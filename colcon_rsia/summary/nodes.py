# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A node of the summary: its labelled publishers and its other endpoints.

Locations are ``"path/relative/to/package:line"`` strings.
"""

from dataclasses import dataclass
from dataclasses import field
from typing import List
from typing import Optional

from colcon_rsia.summary.kinds import ORIGIN_AST


@dataclass
class Evidence:
    """Why a label was given: a kind and a location."""

    kind: str      # publish_site | timer | rate_loop | subscriber | path ...
    location: str
    detail: str = ''


@dataclass
class TopicParam:
    """A topic name taken from a parameter, with its default."""

    name: str
    default: Optional[str]
    namespace: str                # of the NodeHandle that reads it
    # what the code joins around the value (`topic + "_filtered"`)
    prefix: str = ''
    suffix: str = ''


@dataclass
class Trigger:
    """An input of a node whose callback reaches a publish site unpaced.

    ``kind`` is subscriber, service or action; ``all`` stands for every
    input of the node (the paper's rule) where the inputs that drive the
    publisher cannot be told apart, and ``detail`` then says why.
    """

    kind: str
    name: Optional[str]           # the topic/service as written
    location: str                 # where the input is created
    detail: str                   # the call path, or why all inputs
    sync: Optional[str] = None    # the synchronizer the input feeds
    every: Optional[int] = None   # publishes every n-th message


@dataclass
class LabelledPublisher:
    """A publisher of a node with its rate label."""

    topic: Optional[str]
    topic_is_literal: bool
    msg_type: Optional[str]
    api: str
    handle: Optional[str]
    namespace: Optional[str]
    location: str
    label: str
    pattern: str
    rate_hz: Optional[float]
    publish_sites: List[str] = field(default_factory=list)
    evidence: List[Evidence] = field(default_factory=list)
    topic_param: Optional[TopicParam] = None
    # dependent publishers: the inputs that drive them (None: independent,
    # or a summary written before triggers were recorded)
    triggers: Optional[List[Trigger]] = None
    # the rate its own timers or Rate loops give every publish site, when
    # one constant (also for a node without inputs), and which of the two
    paced_rate_hz: Optional[float] = None
    paced_by: Optional[str] = None
    # 'ast', or 'tokens': read from the tokens of a call the parse lost
    origin: str = ORIGIN_AST
    # where a function of the package's library makes it, when `location`
    # is the node's call of that function
    made_in: Optional[str] = None


@dataclass
class NodeSubscriber:
    """A subscription of a node."""

    topic: Optional[str]
    topic_is_literal: bool
    msg_type: Optional[str]
    api: str
    callback: Optional[str]
    namespace: Optional[str]
    location: str
    topic_param: Optional[TopicParam] = None
    origin: str = ORIGIN_AST           # as LabelledPublisher.origin
    made_in: Optional[str] = None      # as LabelledPublisher.made_in


@dataclass
class NodeTimer:
    """A timer of a node."""

    api: str
    callback: Optional[str]
    period: str
    rate_hz: Optional[float]
    location: str


@dataclass
class NodeService:
    """A service server of a node."""

    name: Optional[str]
    api: str
    callback: Optional[str]
    location: str


@dataclass
class NodeClient:
    """A service client of a node."""

    name: Optional[str]
    api: str
    location: str


@dataclass
class NodeAction:
    """An action server or client of a node."""

    name: Optional[str]
    api: str
    role: str
    callbacks: List[str]
    location: str


@dataclass
class Root:
    """Where a call path of the node starts."""

    function: str
    kind: str
    location: str


@dataclass
class Node:
    """One node (executable or nodelet) with its labelled facts."""

    id: str
    package: str
    executable: str
    kind: str                      # executable | nodelet | component | plugin
    # the node name and namespace its code gives (ros::init,
    # rclcpp::Node's constructor); a launch file may override both
    name: Optional[str] = None
    namespace: Optional[str] = None
    sources: List[str] = field(default_factory=list)
    # every file of the package the node's code is read from (sources,
    # headers, modules): what a change must touch to change the node
    files: List[str] = field(default_factory=list)
    publishers: List[LabelledPublisher] = field(default_factory=list)
    subscribers: List[NodeSubscriber] = field(default_factory=list)
    timers: List[NodeTimer] = field(default_factory=list)
    services: List[NodeService] = field(default_factory=list)
    actions: List[NodeAction] = field(default_factory=list)
    clients: List[NodeClient] = field(default_factory=list)
    roots: List[Root] = field(default_factory=list)
    # a plugin: the base class it is exported with, and the host that
    # loads it (colcon_rsia.package.plugin_hosts) when the base is known
    base_class: Optional[str] = None
    host: Optional[str] = None
    plugin_class: Optional[str] = None
    # the nodelets the node's code loads itself (nodelet::Loader::load)
    loads: List['LoadedNodelet'] = field(default_factory=list)


@dataclass
class LoadedNodelet:
    """A nodelet a node loads in its code: its name and plugin type."""

    name: str
    type: str
    location: str


def node_from_dict(data):
    """Build a node from its dict (KeyError, TypeError when malformed)."""
    publishers = []
    for p in data.get('publishers', []):
        p = dict(p)
        p['evidence'] = [Evidence(**e) for e in p.get('evidence', [])]
        if p.get('topic_param'):
            p['topic_param'] = TopicParam(**p['topic_param'])
        if p.get('triggers') is not None:
            p['triggers'] = [Trigger(**t) for t in p['triggers']]
        publishers.append(LabelledPublisher(**p))
    subscribers = []
    for s in data.get('subscribers', []):
        s = dict(s)
        if s.get('topic_param'):
            s['topic_param'] = TopicParam(**s['topic_param'])
        subscribers.append(NodeSubscriber(**s))
    return Node(
        id=data['id'], package=data['package'],
        executable=data['executable'], kind=data['kind'],
        name=data.get('name'), namespace=data.get('namespace'),
        sources=list(data.get('sources', [])),
        files=list(data.get('files', [])),
        publishers=publishers,
        subscribers=subscribers,
        timers=[NodeTimer(**t) for t in data.get('timers', [])],
        services=[NodeService(**s) for s in data.get('services', [])],
        actions=[NodeAction(**a) for a in data.get('actions', [])],
        clients=[NodeClient(**c) for c in data.get('clients', [])],
        roots=[Root(**r) for r in data.get('roots', [])],
        base_class=data.get('base_class'), host=data.get('host'),
        plugin_class=data.get('plugin_class'),
        loads=[LoadedNodelet(**x) for x in data.get('loads', [])])
