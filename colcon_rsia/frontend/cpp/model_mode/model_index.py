# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What code and the model headers declare, read from their text.

The stand-ins (before a unit's first parse) and the recovery (after it)
both ask which names a text or the model declares, and which model header
declares a name.
"""

import re
import threading

from colcon_rsia.frontend.cpp.model_mode.headers import model_header_texts
from colcon_rsia.frontend.cpp.model_mode.source_names import COMMENT_OR_STRING

_lock = threading.Lock()

_DECLARATION = re.compile(
    r'\bnamespace\s+((?:\w+\s*::\s*)+\w+)\s*\{|'
    r'\b(?:class|struct|union|enum(?:\s+class)?|namespace)\s+'
    r'(?:\w+\s+)?(\w+)\s*(?:final\s*)?[:{]|'
    r'\busing\s+(\w+)\s*=|\btypedef\b[^;{}]*?\b(\w+)\s*;|'
    r'^\s*#\s*define\s+(\w+)', re.MULTILINE)


def declared_names(texts):
    """Names that classes, namespaces, aliases and macros of texts declare."""
    names = set()
    for text in texts:
        # `class X  // : public Base` then `{` on the next line
        code = COMMENT_OR_STRING.sub(' ', text)
        for match in _DECLARATION.finditer(code):
            if _aliases_namesake(code, match):
                continue
            # (each namespace of `namespace autoware::planning {`)
            names.update(part.strip() for g in match.groups() if g
                         for part in g.split('::'))
    return names


def _aliases_namesake(code, match):
    """Whether a declaration is an alias of its namesake elsewhere.

    `using PointCloud = pcl::PointCloud<P>;` and `typedef pcl::IndicesPtr
    IndicesPtr;` declare nothing of pcl's: pcl::PointCloud stays missing
    (and repairable) when the package opens a `namespace pcl` of its own.
    """
    alias, typedef = match.group(3), match.group(4)
    if alias:
        end = code.find(';', match.end())
        target = code[match.end():None if end < 0 else end]
        return re.search(r'::\s*' + alias + r'\b', target) is not None
    if typedef:
        return re.search(r'::\s*' + typedef + r'\b',
                         match.group(0)[:-1]) is not None
    return False


_model_declarations = []


def model_declarations():
    """The names the model headers declare (read once)."""
    texts = model_header_texts()
    with _lock:
        if not _model_declarations:
            _model_declarations.append(declared_names(
                text for _, text in texts))
        return _model_declarations[0]


_model_header_index = []
# a function at namespace level (`Logger get_logger(const std::string &);`):
# a repair of one of its calls includes the model header instead of
# declaring a catch-all the call would prefer
_FUNCTION_DECLARED = re.compile(
    r'^(?!return\b)(?:[A-Za-z_][\w:<>,]*(?:\s+[\w:<>,]+)*\s*[*&]*\s*)?'
    r'\b([a-z_]\w*)\s*\(', re.MULTILINE)
_NAMESPACE_OPENED = re.compile(r'\bnamespace\s+(\w+)\s*\{')


# `extern const std::string RGB8, RGBA8, ...;` at namespace level (its list
# may go on over indented lines)
_EXTERN_DECLARED = re.compile(r'^extern\s+[^;(){}]*;', re.MULTILINE)


def _extern_names(text):
    """The names of the variables the extern declarations of a text declare."""
    names = set()
    for match in _EXTERN_DECLARED.finditer(text):
        *_, first = match.group(0)[:-1].split(',')[0].split()
        names.update([first.lstrip('*&')] + [
            name.strip() for name in match.group(0)[:-1].split(',')[1:]])
    return names


def model_headers_declaring(name):
    """Every model header (relative path) declaring a qualified name.

    (A library's ROS 1 and ROS 2 headers may both: publisher.h and
    publisher.hpp.)
    """
    *namespaces, short = name.split('::')
    texts = model_header_texts()
    with _lock:
        if not _model_header_index:
            for path, text in texts:
                # what a namespace declares: the model headers do not
                # indent namespace bodies, members are indented
                top_level = '\n'.join(
                    line for line in text.split('\n')
                    if line[:1] not in (' ', '\t'))
                _model_header_index.append((
                    path, set(_NAMESPACE_OPENED.findall(text)),
                    declared_names([top_level]) |
                    set(_FUNCTION_DECLARED.findall(top_level)) |
                    _extern_names(text)))
    return [path for path, opened, names in _model_header_index
            if namespaces[:1] and namespaces[0] in opened and short in names]


_model_header_words = []
_CLASS_NAMED = re.compile(r'\b(?:class|struct)\s+(\w+)')
_NAMESPACE_NAMED = re.compile(r'\bnamespace\s+(\w+)')


def _header_words():
    """Per model header: the namespaces and the classes it names (once)."""
    texts = model_header_texts()
    with _lock:
        if not _model_header_words:
            _model_header_words.extend(
                (set(_NAMESPACE_NAMED.findall(text)),
                 set(_CLASS_NAMED.findall(text))) for _, text in texts)
    return _model_header_words


def model_declares_class(name):
    """Whether a model header declares (or names) a class `name`."""
    return any(name in classes for _, classes in _header_words())


def model_declares_in(top, name):
    """Whether a model header of namespace `top` declares `name` in it.

    (Roughly: a header that opens `top` and names a namespace or class
    `name`; a model library's declarations may live in rsia_model/.)
    """
    return any(top in namespaces and (name in namespaces or name in classes)
               for namespaces, classes in _header_words())
