# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The package summary: the content of ``summary.json``, and its checks.

:class:`PackageSummary` holds the nodes of a package with their labelled
publishers; everything after the analysis (graph, impact, reports) reads
it. Reading one checks every field's type: a summary is data anyone can
write.
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

from colcon_rsia.summary.coverage import CallSiteCoverage
from colcon_rsia.summary.coverage import Coverage
from colcon_rsia.summary.coverage import UnitCoverage
from colcon_rsia.summary.nodes import Evidence
from colcon_rsia.summary.nodes import LabelledPublisher
from colcon_rsia.summary.nodes import LoadedNodelet
from colcon_rsia.summary.nodes import Node
from colcon_rsia.summary.nodes import node_from_dict
from colcon_rsia.summary.nodes import NodeAction
from colcon_rsia.summary.nodes import NodeClient
from colcon_rsia.summary.nodes import NodeService
from colcon_rsia.summary.nodes import NodeSubscriber
from colcon_rsia.summary.nodes import NodeTimer
from colcon_rsia.summary.nodes import Root
from colcon_rsia.summary.nodes import TopicParam
from colcon_rsia.summary.nodes import Trigger

SUMMARY_SCHEMA = 'colcon-rsia/summary@1'


@dataclass
class Phases:
    """Where a package's analysis time went (wall seconds)."""

    # CMake asked which sources make which node (a package never built is
    # configured in the sandbox first)
    configure: float = 0.0
    # the units and their arguments: the compile database, the model
    # mode's stand-ins and include scan
    prepare: float = 0.0
    # the units' facts: the caches, then libclang's parses and the walks
    parse: float = 0.0
    # nodes, labels, coverage from the facts
    assemble: float = 0.0
    # the Python nodes
    python: float = 0.0

    @classmethod
    def from_dict(cls, data):  # noqa: D102
        return cls(**data)


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
    phases: Optional[Phases] = None

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
            nodes = [node_from_dict(n) for n in data['nodes']]
            summary = cls(
                package=data['package'], path=data['path'],
                tool_version=data['tool_version'],
                header_mode=data.get('header_mode', 'exact'),
                nodes=nodes, diagnostics=list(data.get('diagnostics', [])),
                seconds=data.get('seconds', 0.0),
                coverage=Coverage.from_dict(data['coverage'])
                if data.get('coverage') else None,
                phases=Phases.from_dict(data['phases'])
                if data.get('phases') else None)
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


# {summary class: {field: declared type}}, for _check_types
_FIELD_TYPES = {cls: get_type_hints(cls) for cls in (
    PackageSummary, Node, LabelledPublisher, Evidence, TopicParam, Trigger,
    NodeSubscriber, NodeTimer, NodeService, NodeClient, NodeAction, Root,
    LoadedNodelet, Coverage, UnitCoverage, CallSiteCoverage, Phases)}
