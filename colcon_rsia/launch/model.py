# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The results of reading launch files: node instances and notes."""

from dataclasses import dataclass
from dataclasses import field
from typing import Dict
from typing import List
from typing import Optional
from typing import Tuple


class LaunchError(Exception):
    """A launch file that cannot be read at all (one sentence)."""


@dataclass
class NodeInstance:
    """One node, nodelet or component the launch files start.

    Any of ``package``, ``executable``, ``name`` and ``namespace`` is None
    when it cannot be determined statically; ``unresolved`` then says why.
    """

    package: Optional[str]
    executable: Optional[str]
    name: Optional[str]
    namespace: Optional[str]
    remaps: List[Tuple[str, str]] = field(default_factory=list)
    params: Dict[str, object] = field(default_factory=dict)
    kind: str = 'node'
    location: str = ''
    unresolved: List[str] = field(default_factory=list)
    # the command line's words that are no remap or parameter (a ROS 1
    # spawner's controller names)
    args: List[str] = field(default_factory=list)


@dataclass
class LaunchResult:
    """Every instance a launch file starts, with what was not understood."""

    instances: List[NodeInstance] = field(default_factory=list)
    unresolved: List[str] = field(default_factory=list)
    files: List[str] = field(default_factory=list)
    # ROS 1: every parameter the files set, by absolute name
    global_params: Dict[str, object] = field(default_factory=dict)
