# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The wrappers a package offers the packages analysed after it.

``<build base>/<pkg>/rsia/wrappers.json`` holds the summaries of a
library package's functions that make endpoints; the analysis of a
package reads those of the packages it depends on.
"""

from dataclasses import asdict
from dataclasses import dataclass
from dataclasses import field
import hashlib
import json
import os
from typing import List

from colcon_rsia.safe_files import read_bytes
from colcon_rsia.safe_files import write_json_atomically
from colcon_rsia.summary.store import RSIA_DIRNAME

WRAPPERS_FILENAME = 'wrappers.json'
WRAPPERS_SCHEMA = 'colcon-rsia/wrappers@1'


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


def write_wrappers(package_build_base, package_path, wrappers):
    """Store the summaries of a package's wrapper functions (or none)."""
    path = os.path.join(package_build_base, RSIA_DIRNAME, WRAPPERS_FILENAME)
    if not wrappers:
        try:
            os.unlink(path)
        except OSError:
            pass
        return
    write_json_atomically(path, {
        'schema': WRAPPERS_SCHEMA, 'path': package_path,
        'wrappers': [asdict(w) for w in wrappers]})


def read_workspace_wrappers(package_build_base, package_dirs):
    """The wrapper summaries the workspace's other packages stored.

    Every package's output is a sibling of this one's under the build base;
    a file whose package is no longer in the workspace (``package_dirs``)
    or that cannot be read is left out: its calls give no facts, as before
    its package was analysed.
    """
    build_base = os.path.dirname(os.path.abspath(package_build_base))
    own = os.path.basename(os.path.abspath(package_build_base))
    wanted = {os.path.abspath(d) for d in package_dirs}
    found = []
    try:
        names = sorted(os.listdir(build_base))
    except OSError:
        return found
    for name in names:
        path = os.path.join(build_base, name, RSIA_DIRNAME, WRAPPERS_FILENAME)
        if name == own or not os.path.isfile(path):
            continue
        try:
            data = json.loads(read_bytes(path).decode('utf-8'))
            if data.get('schema') != WRAPPERS_SCHEMA or \
                    data.get('path') not in wanted:
                continue
            found.extend(WrapperSummary(**w) for w in data['wrappers'])
        except (OSError, ValueError, KeyError, TypeError, AttributeError,
                RecursionError):
            continue
    return found


def wrappers_digest(wrappers):
    """A digest of wrapper summaries: the units calling them depend on it."""
    if not wrappers:
        return None
    return hashlib.sha1(json.dumps(
        sorted((asdict(w) for w in wrappers), key=lambda w: w['usr']),
        sort_keys=True).encode()).hexdigest()
