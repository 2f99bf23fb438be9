# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A unit parsed before its package learnt what it lacks, seeded again.

A unit starts with the repairs its package's (and the workspace's) units
parsed before it shared (store.seed_repairs). The units are parsed in
parallel and in no particular order: a unit parsed early keeps the errors
of names that a unit parsed after it repaired, or showed missing. Once
every unit of the package is parsed, such a unit, left with errors that
name what the shared repairs now hold, is worth one more parse, seeded
with them. The others are not parsed again: one more parse costs as much
as the first.
"""

import os
import re

from colcon_rsia import safe_files
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import is_edit
from colcon_rsia.frontend.cpp.model_mode.recovery.loop import \
    package_declarations
from colcon_rsia.frontend.cpp.model_mode.recovery.loop import \
    repair_header_of

_QUOTED_NAME = re.compile(r"'(?:[\w:]*::)?([A-Za-z_]\w*)")


def reseed(entry, facts, errors, *, package_path, workspace=None):
    """Seed a unit left with errors with what its package learnt since.

    Only a unit whose own code has errors, that was not repaired (its
    facts were complete), and whose errors name a repair the package's
    shared ones hold now and its own lack (or are at the place of a shared
    edit).

    :param facts: the unit's facts from its parse (TuFacts)
    :param errors: (file, line, message) of the errors its parse left
    :param workspace: the store.WorkspaceRepairs, or None
    :returns: a function that puts the unit's repairs back as they were
      (its new parse was no better), or None: not worth another parse
    """
    header = repair_header_of(entry.arguments)
    if header is None or not facts.package_errors or facts.repair_rounds:
        return None
    names, places = set(), set()
    for file, line, message in errors:
        names.update(_QUOTED_NAME.findall(message))
        places.add((os.path.abspath(file), int(line)))
    before = store.read_records(header)
    learnt = store.shared_seeds(
        header, package_declarations(package_path), workspace) - set(before)
    if not any(_answers(repair, names, places) for repair in learnt):
        return None
    relative = safe_files.display(os.path.relpath(entry.file, package_path))
    store.add_repairs(header, relative, learnt, store.SEEDED)
    return lambda: store.write_records(header, relative, before)


def _answers(repair, names, places):
    """Whether a repair is of a name the errors name, or at their place."""
    kind, name = repair
    if is_edit(kind):
        # `<file>:<line>:<column>`
        file, line, _ = name.rsplit(':', 2)
        return (os.path.abspath(file), int(line)) in places
    return name.rsplit('::', 1)[-1] in names
