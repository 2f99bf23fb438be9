# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The namespaces the sources open, and what they write in them.

Read from the sources' text without comments and literals (code_only).
"""

import re

# a namespace opened or used (`namespace a::b {`, `using namespace a;`)
_NAMESPACE_NAMED = re.compile(r'\bnamespace\s+(\w+(?:\s*::\s*\w+)*)')
_NAMESPACE_BODY = re.compile(r'\bnamespace\s+(\w+(?:\s*::\s*\w+)*)\s*\{')
# `using a::b::name;` (its qualifier, then the name)
_USING_NAME = re.compile(
    r'\busing\s+(?:::\s*)?((?:[A-Za-z_]\w*\s*::\s*)+)([A-Za-z_]\w*)\s*;')
# a name written without a qualifier or an object before it
_UNQUALIFIED = re.compile(r'(?<![\w:.>])[A-Za-z_]\w*')
_BRACE = re.compile(r'[{}]')
_CALLED = re.compile(r'(?<![\w:.>~])([A-Za-z_]\w*)\s*\(')
_CLASS_OR_SCOPE = re.compile(
    r'\b(?:class|struct|union|enum|namespace)\s+(?:[A-Z_][A-Z0-9_]*\s+)?'
    r'(\w+)|(\w+)\s*::')


def parts(qualified):
    """`a :: b::` as ('a', 'b')."""
    return tuple(part.strip() for part in qualified.split('::')
                 if part.strip())


def namespace_openings(codes):
    """Every `namespace a::b` (and `using namespace a`), as parts."""
    return {parts(match) for code in codes
            for match in _NAMESPACE_NAMED.findall(code)}


def opens(opening, namespace):
    """Whether an opening (parts) opens `namespace` (`a::b`).

    Code inside `namespace a` writes `namespace b` for `a::b`: `namespace
    b` and `namespace a::b` (and deeper) both count.
    """
    *parents, last = namespace.split('::')
    return opening[:1] == (last,) or \
        opening[:len(parents) + 1] == (*parents, last)


def using_declarations(codes):
    """Every `using a::b::name;` of the sources, as (('a', 'b'), 'name')."""
    return {(parts(qualifier), name) for code in codes
            for qualifier, name in _USING_NAME.findall(code)}


def names_in_bodies(namespace, codes, openings):
    """What the sources write in their `namespace` blocks: (names, functions).

    names: every name written unqualified there, declared or only used (a
    superset of what the sources declare in a namespace they add to:
    `namespace pcl { inline int getFieldIndex(...) ... }`); functions: those
    of them written before `(` and never as a class or a scope.

    :param openings: the sources' namespace_openings
    """
    names, functions, classes = set(), set(), set()
    # the namespaces they open inside it (`namespace a::b {` for `a`)
    *parents, last = namespace.split('::')
    for opening in openings:
        for prefix in ((last,), (*parents, last)):
            if opening[:len(prefix)] == prefix and len(opening) > len(prefix):
                names.add(opening[len(prefix)])
                classes.add(opening[len(prefix)])
    for body in _bodies(namespace, codes):
        names.update(_UNQUALIFIED.findall(body))
        functions.update(_CALLED.findall(body))
        classes.update(name for pair in _CLASS_OR_SCOPE.findall(body)
                       for name in pair if name)
    return names, functions - classes


def _bodies(namespace, codes):
    """The text of every block of the sources opening `namespace`."""
    for code in codes:
        for match in _NAMESPACE_BODY.finditer(code):
            if not opens(parts(match.group(1)), namespace):
                continue
            start = end = match.end()
            depth = 1
            while depth and end < len(code):
                brace = _BRACE.search(code, end)
                if brace is None:
                    end = len(code)
                    break
                depth += 1 if brace.group() == '{' else -1
                end = brace.end()
            yield code[start:end]
