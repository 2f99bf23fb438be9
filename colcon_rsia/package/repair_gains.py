# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the parse of a unit lost: what repairing it may win.

"Repair only when it pays" (the model mode's rounds, recovery/loop.py)
parses a unit again only where these count something: an endpoint call
the source shows without a fact, a publish or timer read from tokens, or
a node class the unit constructs whose constructor the parse cannot reach.
"""

import collections
import os
import re
import threading

from colcon_rsia import safe_files
from colcon_rsia.package import coverage
from colcon_rsia.package.call_sites import cxx_call_sites
from colcon_rsia.summary.kinds import ORIGIN_AST
from colcon_rsia.summary.kinds import ORIGIN_TOKENS


def unrecorded_calls(tu, facts, package_path):
    """How many calls of the unit the AST lost: what a repair may win.

    The endpoint call sites of coverage (call_sites.py) in the unit's
    source and the package headers it includes without a fact of the AST,
    the publish sites and timers read from tokens, and the package classes
    the unit constructs without reaching their constructor
    (:func:`lost_constructions`): where there is none, repairing the unit
    pays nothing.
    """
    files = [tu.spelling] + [
        i.include.name for i in tu.get_includes()
        if i.include is not None and _inside(i.include.name, package_path)]
    # a fact read from tokens is approximate (names as written, no types):
    # the AST's is wanted
    origins = collections.defaultdict(set)
    coverage.fact_lines([facts], origins)
    lines = collections.defaultdict(list)
    for (file, role, line), found in origins.items():
        if ORIGIN_AST in found:
            lines[(file, role)].append(line)
    missing = sum(1 for fact in facts.publish_sites + facts.timers
                  if fact.origin == ORIGIN_TOKENS)
    for file in dict.fromkeys(os.path.abspath(f) for f in files):
        relative = os.path.relpath(file, package_path)
        for line, role, _ in _call_sites_of(file):
            if not any(abs(line - recorded) <= coverage.LINE_SLACK
                       for recorded in lines.get((relative, role), ())):
                missing += 1
    return missing + len(lost_constructions(tu, facts, package_path))


def lost_constructions(tu, facts, package_path):
    """The package classes the unit constructs but cannot reach.

    A class of a package header whose body has an error (an unknown macro
    after a method, a member of an unknown type) may be left without the
    constructor a call needs: ``std::make_shared<Node>(options)`` in a
    ``main`` then makes no call edge, and the node reaches none of the
    code of its class, although no endpoint call of the unit is lost. The
    names of such classes the unit's own file constructs (``new C``,
    ``make_shared<C>``, ``C name(...)``) without a call of their
    constructor among the facts.
    """
    # (imported here: analysis.py, which imports this module, is used
    # without libclang where nothing is parsed)
    import clang.cindex as ci
    from colcon_rsia.frontend.cpp.model_mode.source_names import \
        COMMENT_OR_STRING
    main = os.path.abspath(tu.spelling)
    errors = collections.defaultdict(list)
    for diagnostic in tu.diagnostics:
        location = diagnostic.location
        if diagnostic.severity >= ci.Diagnostic.Error and location.file:
            file = os.path.abspath(location.file.name)
            if file != main and _inside(file, package_path):
                errors[file].append(location.offset)
    if not errors:
        return set()
    broken = set()
    for cursor in _class_definitions(tu.cursor, errors):
        extent = cursor.extent
        file = os.path.abspath(extent.start.file.name)
        if any(extent.start.offset <= offset <= extent.end.offset
               for offset in errors[file]) and \
                _declares_constructor(file, extent, cursor.spelling):
            # (a class without a constructor of its own is constructed by
            # no call a fact could show)
            broken.add(cursor.spelling)
    if not broken:
        return set()
    try:
        code = COMMENT_OR_STRING.sub(' ', safe_files.read_text(
            main, errors='replace'))
    except OSError:
        return set()
    called = [call.callee for call in facts.calls]
    return {name for name in broken
            if _constructs(code, name) and not _reaches_constructor(
                called, name)}


def _declares_constructor(file, extent, name):
    """Whether a class's text declares a constructor (as written)."""
    try:
        text = safe_files.read_bytes(file)[
            extent.start.offset:extent.end.offset].decode('latin-1')
    except OSError:
        return False
    return re.search(
        r'(?<![~\w])' + re.escape(name) + r'\s*\(', text) is not None


def _class_definitions(cursor, files):
    """Definitions of classes in `files`, in namespaces or at the top."""
    import clang.cindex as ci
    kinds = (ci.CursorKind.CLASS_DECL, ci.CursorKind.STRUCT_DECL,
             ci.CursorKind.CLASS_TEMPLATE)
    for child in cursor.get_children():
        if child.kind == ci.CursorKind.NAMESPACE:
            yield from _class_definitions(child, files)
        elif child.kind in kinds and child.is_definition() and \
                child.extent.start.file is not None and \
                os.path.abspath(child.extent.start.file.name) in files:
            yield child


def _reaches_constructor(callees, name):
    """Whether a callee is a constructor of class (or template) `name`."""
    name = re.escape(name)
    constructor = re.compile(rf'@S(?:T>[^@]*)?@{name}@F@{name}#')
    return any(constructor.search(callee) for callee in callees)


def _constructs(code, name):
    """Whether code constructs class `name` (not: names it in a typedef)."""
    qualified = r'(?:[\w:]+::)?' + re.escape(name)
    for match in re.finditer(
            r'\b(?:make_shared|make_unique|allocate_shared)\s*<\s*' +
            qualified + r'\s*[>,]|\bnew\s+' + qualified + r'\b|'
            r'(?<![\w:<])' + qualified + r'\s+\w+\s*[({;]', code):
        # `typedef ns::C C;`, `friend class C;`, `class C c_;`: a
        # declaration, or a member whose construction is the class's own
        before = code[max(0, match.start() - 40):match.start()].split()
        if not before or before[-1] not in _NOT_A_CONSTRUCTION:
            return True
    return False


_NOT_A_CONSTRUCTION = frozenset({
    'typedef', 'friend', 'class', 'struct', 'using', 'extern'})


_call_sites = {}
_call_sites_lock = threading.Lock()


def _call_sites_of(path):
    """The endpoint call sites a C++ file shows (read once per content)."""
    try:
        text = safe_files.read_text(path, errors='replace')
    except OSError:
        return []
    key = (path, hash(text))
    with _call_sites_lock:
        found = _call_sites.get(key)
    if found is None:
        found = cxx_call_sites(text)
        with _call_sites_lock:
            _call_sites[key] = found
    return found


def _inside(file, directory):
    return safe_files.is_inside(os.path.abspath(file), directory)
