# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Where a unit's repairs are kept, and what its package shares.

A unit's repairs are data: ``<stub dir>/rsia_model/repair/<unit>.json``
holds one record per repair (its kind, the name it declares or the place
it edits, and the id of the rule that made it, see :mod:`.rules`). The
repair header the parse force-includes is rendered from them
(:mod:`.render`) each time they change; nothing is read back from it.
"""

import hashlib
import json
import os
import re
import threading

from colcon_rsia import safe_files
from colcon_rsia.frontend.cpp.model_mode.model_index import \
    model_declarations
from colcon_rsia.frontend.cpp.model_mode.recovery.declared import \
    is_declared
from colcon_rsia.frontend.cpp.model_mode.recovery.declared import \
    one_kind_each
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import FUNCTION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import HEADER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import INCLUDES
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import is_edit
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_KINDS
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import \
    MEMBER_TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import OBJECT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import STD_HEADER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TEMPLATE_USE
from colcon_rsia.frontend.cpp.model_mode.recovery.render import render
from colcon_rsia.frontend.cpp.model_mode.stubs import REPAIR_DIR
from colcon_rsia.frontend.cpp.model_mode.stubs import write_atomically

REPAIRS_SCHEMA = 'colcon-rsia/repairs@1'
# the rule id of repairs a unit starts with, from its package's other units
SEEDED = 'seeded'


def repair_header(stub_dir, source):
    """The path of a unit's repair header (one per main file)."""
    digest = hashlib.sha1(os.path.abspath(source).encode(
        'utf-8', 'surrogateescape')).hexdigest()[:16]
    stem = re.sub(r'\W', '_', os.path.basename(source))[:40]
    return os.path.join(stub_dir, REPAIR_DIR, f'{stem}_{digest}.h')


def _records_path(header):
    return os.path.splitext(header)[0] + '.json'


def ensure_repair_header(path, source):
    """Create an empty repair header, so that it can be force-included."""
    if not os.path.isfile(path):
        write_atomically(path, render({}, source))


def read_records(path):
    """{(kind, name): rule id} of the repairs of a unit's repair header."""
    try:
        with open(_records_path(path), encoding='utf-8') as h:
            data = json.load(h)
        return {(r['kind'], r['name']): r['rule'] for r in data['repairs']}
    except (OSError, ValueError, KeyError, TypeError):
        return {}


def read_repairs(path):
    """{(kind, qualified name)} already declared in a repair header."""
    return set(read_records(path))


def add_repairs(path, source, repairs, rule=None):
    """Add repairs to a unit's; return whether they grew.

    :param repairs: {(kind, name): rule id}, or a set of (kind, name)
      made by `rule`
    """
    if not isinstance(repairs, dict):
        repairs = {repair: rule or SEEDED for repair in repairs}
    known = read_records(path)
    # a member declared as a value and then used as `obj.name<T>()`, a
    # name as `name<T>(x)` after `using ns::name;`
    uses = {name for kind, name in repairs if kind == TEMPLATE_USE}
    templates = {MEMBER: MEMBER_TEMPLATE, OBJECT: FUNCTION}
    rules = {}
    for (kind, name), made_by in list(known.items()) + list(repairs.items()):
        if kind == TEMPLATE_USE:
            continue
        if kind in templates and name.rsplit('::', 1)[-1] in uses:
            kind = templates[kind]
        rules.setdefault((kind, name), made_by)
    merged = one_kind_each(set(rules))
    if merged == set(known):
        return False
    write_records(path, source, {r: rules.get(r) or repairs.get(r) or SEEDED
                                 for r in merged})
    return True


def write_records(path, source, records):
    """Replace a unit's repairs with these, and render its header."""
    write_atomically(_records_path(path), json.dumps({
        'schema': REPAIRS_SCHEMA, 'source': source,
        'repairs': [{'kind': kind, 'name': name, 'rule': rule}
                    for (kind, name), rule in sorted(records.items())]},
        indent=1) + '\n')
    write_atomically(path, render(set(records), source))


# what one unit needed that any unit of the package may need: qualified
# names, macros and standard headers (shared through this file, so that the
# units parsed later start with them and need fewer parses; see also
# WorkspaceRepairs)
SHARED_REPAIRS = 'package.repairs.json'
_shared_lock = threading.Lock()


# the files other units include too
_HEADER_FILES = ('.h', '.hh', '.hpp', '.hxx', '.h++', '.ipp', '.inl')


def _shareable(repair):
    kind, name = repair
    if is_edit(kind):
        # a place in one file: in a header, every unit that includes it
        # meets the same error there (in other units the edit is unused)
        return name.rpartition(':')[0].rpartition(':')[0].endswith(
            _HEADER_FILES)
    # (a member of a qualified class: with its class, which is shared too)
    return kind in INCLUDES or kind.startswith('macro-') or (
        '::' in name and (kind not in MEMBER_KINDS or
                          '::' in name.rsplit('::', 1)[0]))


class WorkspaceRepairs:
    """What the units of every package of a workspace share.

    A header of one package is included by the units of many: the names
    one unit needed from it, the next unit of any package needs too. Only
    names the workspace's own code declares nowhere are shared this way
    (a unit of another package may include the real declaration).

    :param path: the file they are kept in (beside the packages' outputs)
    :param declared: the names the workspace's C++ files declare
    """

    def __init__(self, path, declared):  # noqa: D107
        self.path = path
        self.declared = frozenset(declared)


def share_repairs(header, repairs, workspace=None):
    """Offer a unit's repairs to the units parsed later.

    To those of its package, and, when `workspace` (a WorkspaceRepairs)
    is given, those of every package.
    """
    offered = {r for r in repairs if _shareable(r)}
    _offer(os.path.join(os.path.dirname(header), SHARED_REPAIRS), offered)
    if workspace is not None:
        # (not a model or stand-in header: a stand-in is written into the
        # package's own stub directory, which another package's units do
        # not see)
        _offer(workspace.path, {
            r for r in offered if r[0] != HEADER and (
                r[0] == STD_HEADER or
                not is_declared(r[1], workspace.declared))})


def withdraw_shared(header, repairs, workspace=None):
    """Offer these repairs no more: clang rejected them in a unit.

    A repair that conflicted with a real declaration a unit includes is a
    guess proven wrong where that declaration is in reach; the units
    parsed later do not start with it (one that needs it finds it again).
    """
    paths = [os.path.join(os.path.dirname(header), SHARED_REPAIRS)] + (
        [workspace.path] if workspace is not None else [])
    for path in paths:
        with _shared_lock, safe_files.directory_lock(os.path.dirname(path)):
            _write_shared(path, _read_shared(path) - set(repairs))
            # (and never offered again: a unit seeded with it before would
            # share it back)
            _write_shared(_withdrawn_path(path),
                          _read_shared(_withdrawn_path(path)) | set(repairs))


def _withdrawn_path(path):
    return os.path.splitext(path)[0] + '.withdrawn.json'


def _write_shared(path, repairs):
    write_atomically(path, json.dumps(sorted(
        [kind, name] for kind, name in repairs)) + '\n')


def _offer(path, offered):
    # the units are parsed in several processes (and packages, at the same
    # time, under a parallel build)
    with _shared_lock, safe_files.directory_lock(os.path.dirname(path)):
        known = _read_shared(path)
        offered = offered - _read_shared(_withdrawn_path(path))
        if not offered <= known:
            _write_shared(path, known | offered)


def seed_repairs(header, source, declared, workspace=None):
    """Start a unit's (empty) repairs with its package's (and workspace's).

    :param workspace: a WorkspaceRepairs, or None
    """
    seeds = shared_seeds(header, declared, workspace)
    return bool(seeds) and add_repairs(header, source, seeds, SEEDED)


def shared_seeds(header, declared, workspace=None):
    """{(kind, name)} a unit starts with: what its package's units shared.

    :param declared: the names the unit's package declares
    :param workspace: a WorkspaceRepairs (the workspace's too), or None
    """
    path = os.path.join(os.path.dirname(header), SHARED_REPAIRS)
    with _shared_lock:
        shared = _read_shared(path)
        if workspace is not None:
            shared |= _read_shared(workspace.path)
    # a unit may include the model header or the package header that
    # another unit lacked: only names declared in neither are seeded
    declared = set(declared) | model_declarations()
    return {r for r in shared
            if r[0] in INCLUDES or not is_declared(r[1], declared)}


def _read_shared(path):
    try:
        with open(path, encoding='utf-8') as h:
            return {(kind, name) for kind, name in json.load(h)}
    except (OSError, ValueError, TypeError):
        return set()
