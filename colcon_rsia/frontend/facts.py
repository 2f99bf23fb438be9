# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The facts: what a front end found in one translation unit or module.

:class:`TuFacts` holds them keyed by function, with no ROS semantics
beyond the role of a call. They are build-time data: the front ends make
them, ``package/`` caches them per translation unit and turns them into
the package summary (:mod:`colcon_rsia.summary`).

Locations are ``"path/relative/to/package:line"`` strings.
"""

from dataclasses import asdict
from dataclasses import dataclass
from dataclasses import field
from dataclasses import fields
from typing import List
from typing import Optional

from colcon_rsia.summary.kinds import ORIGIN_AST
from colcon_rsia.summary.wrapper_store import WrapperSummary

FACTS_SCHEMA = 'colcon-rsia/facts@1'


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
class NameArgument:
    """A string a call passes to a package function, read as a topic would be.

    What one call gives a parameter that the callee makes an endpoint's
    topic of (see node_facts: one endpoint per call).
    """

    index: int                    # the parameter's
    topic: Optional[str]          # the literal, else the expression
    topic_is_literal: bool
    topic_handle: Optional[str] = None
    topic_affixes: Optional[List[str]] = None


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
    # the strings it passes to the callee's string parameters
    name_arguments: List[NameArgument] = field(default_factory=list)
    # a virtual call made on the object itself (`f()`, `this->f()`): it runs
    # the override of the object's own class
    on_this: bool = False

    def __post_init__(self):  # noqa: D105
        # (read back from a cache as dicts)
        self.name_arguments = [
            a if isinstance(a, NameArgument) else NameArgument(**a)
            for a in self.name_arguments]


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
    # the topic is this parameter of the function making the endpoint:
    # each call makes one, of what it passes (node_facts)
    topic_argument: Optional[int] = None
    # where a function of the package's library makes it, when `location`
    # is the executable's call of that function (node_facts)
    made_in: Optional[str] = None


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
    topic_argument: Optional[int] = None  # as PublisherFact.topic_argument
    made_in: Optional[str] = None      # as PublisherFact.made_in


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


# the NodeHandle marker of the handle a function returns (``nh`` of a
# fact, ``alias`` of a HandleAlias): ret:<function USR>
RETURNED_HANDLE = 'ret:'


@dataclass
class NodeHandleFact:
    """The namespace a NodeHandle variable/field was created with."""

    handle: str
    namespace: str                # '' node ns, '~' private, or as written


_UNIT_COUNTS = ('errors', 'package_errors', 'repair_rounds', 'lost_calls')


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
    # the facts may lack: see repair_gains.unrecorded_calls)
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
