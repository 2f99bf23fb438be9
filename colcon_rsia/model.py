# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Plain data of the analysis, and its (de)serialisation.

Two layers:

* **facts** (:class:`TuFacts`): what a front end found in one translation unit
  or Python module, keyed by function; no ROS semantics beyond the role of a
  call. Facts are cached per translation unit.
* **the package summary** (:class:`PackageSummary`): the nodes of a package
  with their labelled publishers; this is what ``summary.json`` holds and
  everything after the analysis (graph, impact, reports) reads.

Locations are ``"path/relative/to/package:line"`` strings.
"""

from dataclasses import asdict
from dataclasses import dataclass
from dataclasses import field
from dataclasses import fields
import math
from typing import get_type_hints
from typing import List
from typing import Optional
from typing import Union

SUMMARY_SCHEMA = 'colcon-rsia/summary@1'
FACTS_SCHEMA = 'colcon-rsia/facts@1'

# labels and patterns of a publisher edge (the paper's Algorithm 1)
INDEPENDENT = 'independent'
DEPENDENT = 'dependent'
PATTERN_NO_SUBSCRIBERS = 'no_subscribers'
PATTERN_TIMER = 'timer'
PATTERN_RATE_LOOP = 'rate_loop'
PATTERN_MIXED = 'mixed'
PATTERN_NONE = 'none'
# a plugin's publish reached only from a method its host calls from its own
# fixed-rate loop (a controller's update())
PATTERN_HOST_PERIODIC = 'host_periodic'

# root kinds
ROOT_MAIN = 'main'
ROOT_NODELET = 'nodelet'
ROOT_SUBSCRIBER = 'subscriber'
ROOT_TIMER = 'timer'
ROOT_SERVICE = 'service'
ROOT_ACTION = 'action'
ROOT_ENTRY = 'entry'  # a function nobody calls: entered from outside
# a publisher's callback run when a subscriber connects or disconnects
ROOT_CONNECT = 'connect'
# a plugin's methods its host calls (colcon_rsia.package.plugin_hosts)
ROOT_HOST_PERIODIC = 'host_periodic'
ROOT_HOST_REQUEST = 'host_request'
ROOT_HOST_SETUP = 'host_setup'


# the mark of a NodeHandle namespace the code builds from a value the
# analysis does not know (`ros::NodeHandle nh(real_name)`), followed by the
# expression as written: names relative to it are not resolved
UNKNOWN_NAMESPACE = '?'

# where a fact comes from: the AST, or the tokens of a call the parse lost
# (colcon_rsia.frontend.cpp.token_facts)
ORIGIN_AST = 'ast'
ORIGIN_TOKENS = 'tokens'


@dataclass
class Function:
    """A function, method, constructor or lambda with a body."""

    id: str            # USR; lambdas: lambda@<file>:<line>:<col>
    name: str          # qualified name; lambdas: lambda@<file>:<line>
    location: str
    class_id: Optional[str] = None  # USR of the enclosing class
    params: List[str] = field(default_factory=list)  # USRs, in order


@dataclass
class ParamBinding:
    """A handle passed as argument `index` of a function (call or bind)."""

    callee: str
    index: int
    handle: str


@dataclass
class Call:
    """A call edge; `kind` is 'call' or 'ref' (address taken, called later)."""

    caller: str
    callee: str
    location: str
    loops: List[str] = field(default_factory=list)
    kind: str = 'call'
    # a call of a virtual method: its qualified name (`ns::Base::run`),
    # which every override of a derived class of the package answers
    virtual: Optional[str] = None


@dataclass
class PublisherFact:
    """A publisher object created in user code."""

    function: Optional[str]
    api: str
    topic: Optional[str]          # as written: the literal, else the expression
    topic_is_literal: bool
    msg_type: Optional[str]
    handle: Optional[str]         # USR of the variable/field holding it
    handle_name: Optional[str]
    location: str
    class_id: Optional[str] = None
    nh: Optional[str] = None      # USR of the NodeHandle used, or a namespace marker
    topic_handle: Optional[str] = None  # the variable holding a non-literal topic
    # [prefix, suffix] the code joins around that variable's value
    topic_affixes: Optional[List[str]] = None
    # 'ast', or 'tokens' where the AST had lost the call
    # (colcon_rsia.frontend.cpp.token_facts)
    origin: str = ORIGIN_AST
    # function ids of the callbacks run when a subscriber connects or
    # disconnects (roots of the node: a lazy node subscribes there)
    status_callbacks: List[str] = field(default_factory=list)


@dataclass
class SubscriberFact:
    """A subscription created in user code."""

    function: Optional[str]
    api: str
    topic: Optional[str]
    topic_is_literal: bool
    msg_type: Optional[str]
    handle: Optional[str]
    callback: Optional[str]       # function id
    location: str
    class_id: Optional[str] = None
    nh: Optional[str] = None
    topic_handle: Optional[str] = None
    topic_affixes: Optional[List[str]] = None
    origin: str = ORIGIN_AST           # as PublisherFact.origin


@dataclass
class ParamRead:
    """A parameter read into a variable (``nh.param("topic", t, "scan")``)."""

    function: str
    name: str
    default: Optional[str]        # the default as written, when a literal
    handle: Optional[str]         # the variable the value goes to
    nh: Optional[str]
    location: str


@dataclass
class TimerFact:
    """A periodic callback registration."""

    function: str
    api: str
    callback: Optional[str]
    period: str                   # the period/rate expression as written
    rate_hz: Optional[float]
    location: str
    origin: str = ORIGIN_AST           # as PublisherFact.origin


@dataclass
class ServiceFact:
    """A service server."""

    function: str
    api: str
    name: Optional[str]
    callback: Optional[str]
    location: str


@dataclass
class ActionFact:
    """An action server or client, or a callback registered on one."""

    function: Optional[str]
    api: str
    role: str                     # server | client
    name: Optional[str]
    callbacks: List[str]
    handle: Optional[str]
    location: str


@dataclass
class PublishSite:
    """A call that publishes through a handle."""

    function: str
    api: str
    handle: Optional[str]
    location: str
    loops: List[str] = field(default_factory=list)
    # under ``if (++count % n == 0)``: publishes every n-th call
    every: Optional[int] = None
    origin: str = ORIGIN_AST           # as PublisherFact.origin


@dataclass
class RateObject:
    """An adaptive-sleep object (``ros::Rate``) and its rate when constant."""

    handle: str
    rate_hz: Optional[float]
    expression: str
    location: str


@dataclass
class PacedLoop:
    """A loop whose every iteration runs the sleep() of a rate object."""

    loop: str
    function: str
    rate_handle: str
    location: str                 # of the loop
    sleep_location: str


@dataclass
class SyncFact:
    """A message_filters synchronizer and the handles it takes as inputs."""

    handle: Optional[str]
    inputs: List[str]
    location: str


@dataclass
class Registration:
    """A message_filters callback registration on a handle."""

    function: str
    handle: Optional[str]
    callback: Optional[str]
    location: str


@dataclass
class HostEvent:
    """A callback the hosting process calls on an event of its own.

    ``gazebo::event::Events::ConnectWorldUpdateBegin(cb)``: gzserver calls
    ``cb`` on every simulation step (see package/plugin_hosts.py).
    """

    function: str
    api: str
    callback: Optional[str]
    location: str


@dataclass
class NodeletLoad:
    """``nodelet::Loader::load(name, type, ...)``: a nodelet started in code."""

    function: str
    name: Optional[str]  # None: not a literal
    type: Optional[str]  # its plugin name (pkg/Name); None: not a literal
    location: str


@dataclass
class NodeNameFact:
    """The name (and namespace) a node gives itself in code.

    ``ros::init(argc, argv, "name")``, ``rclcpp::Node("name", "ns")``.
    """

    function: str
    name: Optional[str]           # the literal, None when not a literal
    namespace: Optional[str]
    location: str
    # the parameter of `function` the name is passed in, when it is one:
    # a base class's constructor ``Base(name) : Node(name)``
    name_param: Optional[str] = None


@dataclass
class StringArgument:
    """A string literal passed as argument `index` of a package function."""

    caller: str
    callee: str
    index: int
    value: str


@dataclass
class ClientFact:
    """A service client (it calls a service; it publishes no topic)."""

    function: str
    api: str
    name: Optional[str]
    location: str


@dataclass
class HandleAlias:
    """An object that publishes through another's handle (a wrapper)."""

    alias: str
    handle: str
    location: str


@dataclass
class NodeHandleFact:
    """The namespace a NodeHandle variable/field was created with."""

    handle: str
    namespace: str                # '' node ns, '~' private, or as written


_UNIT_COUNTS = ('errors', 'package_errors', 'repair_rounds', 'lost_calls')


@dataclass
class WrapperSummary:
    """What calling a function of the package does, for other packages.

    A function defined in a ``.cpp`` of a library package
    (``DiagGraphSubscription::subscribe(rclcpp::Node &, size_t)``) whose
    body other packages never see: its summary
    (:mod:`colcon_rsia.frontend.cpp.wrappers`) travels in
    ``<build base>/<pkg>/rsia/wrappers.json`` to the packages analysed
    after it. ``endpoints`` are the fields of ``wrappers.Endpoint``.
    """

    usr: str
    name: str                      # qualified name
    arity: int                     # its parameters
    endpoints: List[dict] = field(default_factory=list)
    publishes_members: List[str] = field(default_factory=list)


@dataclass
class TuFacts:
    """Everything a front end found in one translation unit."""

    source: str
    functions: List[Function] = field(default_factory=list)
    calls: List[Call] = field(default_factory=list)
    publishers: List[PublisherFact] = field(default_factory=list)
    subscribers: List[SubscriberFact] = field(default_factory=list)
    timers: List[TimerFact] = field(default_factory=list)
    services: List[ServiceFact] = field(default_factory=list)
    actions: List[ActionFact] = field(default_factory=list)
    publish_sites: List[PublishSite] = field(default_factory=list)
    rates: List[RateObject] = field(default_factory=list)
    paced_loops: List[PacedLoop] = field(default_factory=list)
    syncs: List[SyncFact] = field(default_factory=list)
    registrations: List[Registration] = field(default_factory=list)
    host_events: List[HostEvent] = field(default_factory=list)
    nodelet_loads: List[NodeletLoad] = field(default_factory=list)
    node_handles: List[NodeHandleFact] = field(default_factory=list)
    bindings: List[ParamBinding] = field(default_factory=list)
    param_reads: List[ParamRead] = field(default_factory=list)
    node_names: List[NodeNameFact] = field(default_factory=list)
    clients: List[ClientFact] = field(default_factory=list)
    handle_aliases: List[HandleAlias] = field(default_factory=list)
    string_arguments: List[StringArgument] = field(default_factory=list)
    plugin_exports: List[List[str]] = field(default_factory=list)
    # [class, base] of the package's classes, and [alias, class] of its
    # type aliases of classes: what a plugin class inherits its methods from
    class_bases: List[List[str]] = field(default_factory=list)
    class_aliases: List[List[str]] = field(default_factory=list)
    # summaries of the unit's functions that make endpoints, for the
    # other packages calling them
    wrappers: List[WrapperSummary] = field(default_factory=list)
    # the package's own files the unit read (its source and headers)
    files: List[str] = field(default_factory=list)
    diagnostics: List[str] = field(default_factory=list)
    # parse errors left in the unit (in all, and in the package's own
    # files), and the parses the model mode's repairs took
    errors: int = 0
    package_errors: int = 0
    repair_rounds: int = 0
    # calls the unit's text shows that its parse lost (errors aside, what
    # the facts may lack: see analysis._unrecorded_calls)
    lost_calls: int = 0
    # [rule id, kind, name or place] of the unit's repairs (model mode)
    repairs: List[List[str]] = field(default_factory=list)

    def to_dict(self):  # noqa: D102
        return asdict(self)

    @classmethod
    def from_dict(cls, data):  # noqa: D102
        types = {
            'functions': Function, 'calls': Call,
            'publishers': PublisherFact, 'subscribers': SubscriberFact,
            'timers': TimerFact, 'services': ServiceFact,
            'actions': ActionFact, 'publish_sites': PublishSite,
            'rates': RateObject, 'paced_loops': PacedLoop,
            'syncs': SyncFact, 'registrations': Registration,
            'host_events': HostEvent, 'nodelet_loads': NodeletLoad,
            'node_handles': NodeHandleFact, 'bindings': ParamBinding,
            'param_reads': ParamRead, 'node_names': NodeNameFact,
            'clients': ClientFact, 'handle_aliases': HandleAlias,
            'string_arguments': StringArgument, 'wrappers': WrapperSummary,
        }
        kwargs = {}
        for f in fields(cls):
            if f.name in _UNIT_COUNTS:
                kwargs[f.name] = int(data.get(f.name, 0))
                continue
            value = data.get(f.name, [] if f.name != 'source' else '')
            if f.name in types:
                value = [types[f.name](**item) for item in value]
            kwargs[f.name] = value
        return cls(**kwargs)

    def extend(self, other):
        """Append all facts of another unit (duplicates removed later)."""
        for f in fields(self):
            if f.name in _UNIT_COUNTS:
                setattr(self, f.name,
                        getattr(self, f.name) + getattr(other, f.name))
            elif f.name != 'source':
                getattr(self, f.name).extend(getattr(other, f.name))


# --- the package summary (summary.json) -----------------------------------

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


TRIGGER_ALL = 'all'


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


@dataclass
class UnitCoverage:
    """How one translation unit parsed."""

    file: str
    errors: int = 0            # parse errors left, in all
    package_errors: int = 0    # of which in the package's own files
    repair_rounds: int = 0     # parses after the first (model mode)
    # publisher/subscription/publish/timer calls the unit's text shows that
    # the parse lost (an error the repairs left that costs a fact; errors
    # that cost none are left unrepaired when repairing does not pay)
    lost_calls: int = 0
    # [rule id, kind, name or place] of the unit's repairs (model mode)
    repairs: List[List[str]] = field(default_factory=list)


@dataclass
class CallSiteCoverage:
    """One publisher/subscription call site the source text shows."""

    file: str
    line: int
    role: str       # 'publisher' | 'subscriber'
    api: str
    recorded: str   # 'node' | 'unit' (facts no node runs) | 'none'
    # of a recorded site: 'ast', or 'tokens' (read where the parse lost it)
    origin: Optional[str] = None


@dataclass
class Coverage:
    """What the analysis understood of a package (see coverage.py)."""

    units: List[UnitCoverage] = field(default_factory=list)
    call_sites: List[CallSiteCoverage] = field(default_factory=list)

    @classmethod
    def from_dict(cls, data):  # noqa: D102
        return cls(
            units=[UnitCoverage(**u) for u in data.get('units', [])],
            call_sites=[CallSiteCoverage(**c)
                        for c in data.get('call_sites', [])])


@dataclass
class PackageSummary:
    """The analysis result of one package: the content of summary.json."""

    package: str
    path: str
    tool_version: str
    header_mode: str = 'exact'
    nodes: List[Node] = field(default_factory=list)
    diagnostics: List[str] = field(default_factory=list)
    seconds: float = 0.0
    schema: str = SUMMARY_SCHEMA
    # optional: summaries of older versions have none
    coverage: Optional[Coverage] = None

    def to_dict(self):
        r"""The summary as JSON data; undecodable names escaped (``\\xe9``).

        File names that are not UTF-8 reach the summary with surrogate
        escapes; every reader of the summary shows them as ``\\xe9``.
        """
        return _escaped(asdict(self))

    @classmethod
    def from_dict(cls, data):
        """Build a summary from its dict; raise ValueError when malformed."""
        if data.get('schema') != SUMMARY_SCHEMA:
            raise ValueError(
                f"unsupported summary schema {data.get('schema')!r} "
                f'(this version reads {SUMMARY_SCHEMA!r})')
        try:
            nodes = [_node_from_dict(n) for n in data['nodes']]
            summary = cls(
                package=data['package'], path=data['path'],
                tool_version=data['tool_version'],
                header_mode=data.get('header_mode', 'exact'),
                nodes=nodes, diagnostics=list(data.get('diagnostics', [])),
                seconds=data.get('seconds', 0.0),
                coverage=Coverage.from_dict(data['coverage'])
                if data.get('coverage') else None)
        except (KeyError, TypeError, AttributeError) as e:
            raise ValueError(f'malformed summary: {e!r}') from None
        _check_types(summary, 'summary')
        ids = [n.id for n in nodes]
        for node_id in sorted({i for i in ids if ids.count(i) > 1}):
            raise ValueError(f"node id '{node_id}' appears more than once")
        return summary


def _check_types(value, where):
    """Raise ValueError unless every field has its declared type.

    A summary is data anyone can write: a wrong type (an int id, a string
    rate, NaN) must stop at loading with one message, not crash the graph
    or end up in the output JSON.
    """
    for f in fields(value):
        _check_value(getattr(value, f.name), _FIELD_TYPES[type(value)][f.name],
                     f'{where}.{f.name}')


def _check_value(item, expected, where):
    origin = getattr(expected, '__origin__', None)
    arguments = getattr(expected, '__args__', ())
    if origin is Union:  # Optional[X]
        if item is None:
            return
        expected = next(a for a in arguments if a is not type(None))
        origin = getattr(expected, '__origin__', None)
        arguments = getattr(expected, '__args__', ())
    if origin is list:
        if not isinstance(item, list):
            raise ValueError(f'{where} is not a list')
        for i, element in enumerate(item):
            _check_value(element, arguments[0], f'{where}[{i}]')
    elif expected is int:
        if isinstance(item, bool) or not isinstance(item, int):
            raise ValueError(f'{where} is not a whole number: {item!r:.40}')
    elif expected is float:
        if isinstance(item, bool) or not isinstance(item, (int, float)) or \
                not math.isfinite(item):
            raise ValueError(f'{where} is not a finite number: {item!r}')
    elif expected in (str, bool):
        if not isinstance(item, expected):
            raise ValueError(
                f'{where} is not a {expected.__name__}: {item!r:.40}')
    elif isinstance(item, expected):
        _check_types(item, where)
    else:
        raise ValueError(f'{where} is not an object')


def _escaped(data):
    from colcon_rsia.safe_files import display
    if isinstance(data, str):
        return display(data)
    if isinstance(data, dict):
        return {_escaped(k): _escaped(v) for k, v in data.items()}
    if isinstance(data, list):
        return [_escaped(v) for v in data]
    return data


def _node_from_dict(data):
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


# {summary class: {field: declared type}}, for _check_types
_FIELD_TYPES = {cls: get_type_hints(cls) for cls in (
    PackageSummary, Node, LabelledPublisher, Evidence, TopicParam, Trigger,
    NodeSubscriber, NodeTimer, NodeService, NodeClient, NodeAction, Root,
    LoadedNodelet, Coverage, UnitCoverage, CallSiteCoverage)}
