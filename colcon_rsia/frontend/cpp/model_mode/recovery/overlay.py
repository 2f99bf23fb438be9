# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A model class answers what it lacks: members added for one unit's parse.

The model headers declare what the analysis needs of each ROS class; the
user's library version has more (a getter overload, a nested ``SharedPtr``,
a member function of a newer release). A member a model class lacks would
make clang drop the statement, or the whole function when a declaration
names it. A repair of kind ``model-member:<shape>`` (``function``,
``type``, ``value``) adds a permissive member to the class: the model
header is given to the parse with the member declared before the class's
closing brace (libclang's unsaved files: the file on disk never changes).
"""

import os
import re
import threading

from colcon_rsia.frontend.cpp.model_mode.headers import model_header_texts
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import ALL_CAPS
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import K_CONSTANT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MODEL_MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import SOURCE_NOISE
from colcon_rsia.frontend.cpp.model_mode.unknown_headers import POINTER_TYPES

FUNCTION_SHAPE = 'function'
TYPE_SHAPE = 'type'
VALUE_SHAPE = 'value'

_WORD = re.compile(r'[A-Za-z_]\w*|::|[{};]|\S')
_PREPROCESSOR = re.compile(r'^[ \t]*#[^\n]*(?:\\\n[^\n]*)*', re.MULTILINE)

_index = {}
_lock = threading.Lock()


def _blank(match):
    return re.sub(r'[^\n]', ' ', match.group(0))


def class_bodies(text):
    """{qualified class name: [(body start, closing brace) offsets]}.

    Namespaces and classes are followed by their braces (comments, strings
    and preprocessor lines blanked; a class declared in both branches of an
    ``#if`` has two bodies).
    """
    code = _PREPROCESSOR.sub(_blank, SOURCE_NOISE.sub(_blank, text))
    bodies = {}
    scopes = []       # (name or '', kind) of each open brace
    pending = None    # ('namespace'|'class', name) until its `{` or `;`
    words = list(_WORD.finditer(code))
    for i, match in enumerate(words):
        word = match.group(0)
        if word in ('namespace', 'class', 'struct') and i + 1 < len(words) \
                and re.match(r'[A-Za-z_]', words[i + 1].group(0)):
            # `enum class X`: an enumeration, not a class to add to
            if not (word == 'class' and i and
                    words[i - 1].group(0) == 'enum'):
                pending = (word, words[i + 1].group(0))
        elif word == ';' or word == '(' and pending and \
                pending[0] != 'namespace':
            pending = None  # a declaration only, or a function's type
        elif word == '{':
            if pending is not None:
                scopes.append((pending[1], pending[0], match.end()))
            else:
                scopes.append(('', '', match.end()))
            pending = None
        elif word == '}' and scopes:
            name, kind, start = scopes.pop()
            if kind in ('class', 'struct'):
                qualified = '::'.join([s[0] for s in scopes if s[0]] + [name])
                bodies.setdefault(qualified, []).append(
                    (start, match.start()))
    return bodies


def _model_index():
    """{qualified class name: relative header} of every model header."""
    with _lock:
        if not _index:
            for relative, text in model_header_texts():
                for name in class_bodies(text):
                    _index.setdefault(
                        name, os.path.join(MODEL_HEADERS_DIR, relative))
        return _index


def model_class(name):
    """The model header defining a class (``rclcpp::QoS``), or None.

    A message spells a class template's instance with its arguments
    (``ns::Name_<std::allocator<void>>``): the template is the class.
    """
    return _model_index().get(re.sub(r'<.*$', '', name).strip())


def model_class_at(path, line):
    """The innermost model class whose body holds a line of a header."""
    if not os.path.abspath(path).startswith(MODEL_HEADERS_DIR + os.sep):
        return None
    try:
        with open(path, encoding='utf-8') as h:
            text = h.read()
    except (OSError, UnicodeDecodeError):
        return None
    offset = sum(len(row) + 1 for row in text.split('\n')[:line - 1])
    found = [(start, name) for name, spans in class_bodies(text).items()
             for start, end in spans if start <= offset <= end]
    return max(found)[1] if found else None


def member_declaration(class_name, member, shape):
    """A permissive member of a class, of the shape its use asks for."""
    short = class_name.rsplit('::', 1)[-1]
    if shape == TYPE_SHAPE:
        if member in POINTER_TYPES:
            return f'using {member} = ::rsia_model::UnknownPointer<{short}>;'
        return f'using {member} = ::rsia_model::Unknown;'
    if shape == VALUE_SHAPE:
        if K_CONSTANT.match(member) or ALL_CAPS.match(member):
            return f'static constexpr int {member} = 1;'
        return f'static ::rsia_model::Any {member};'
    # any arguments, any result: a call clang could not match resolves
    # here, under the class's own name (what the API table reads). Only
    # as the last choice: a C variadic ranks below every conversion, so a
    # call an overload of the class matches still resolves there (taking
    # `RsiaA &&...`, the member would tie with that overload or beat it:
    # an ambiguous call, in every unit the repair is shared with)
    return f'template <class... RsiaA> static ::rsia_model::Any & ' \
        f'{member}(...);'


def overlays(repairs):
    """{model header path: its text with the repairs' members added}."""
    members = {}
    for kind, name in repairs:
        base, _, shape = kind.partition(':')
        if base != MODEL_MEMBER:
            continue
        class_name, member = name.rsplit('::', 1)
        path = model_class(class_name)
        if path is not None:
            members.setdefault(path, {}).setdefault(
                re.sub(r'<.*$', '', class_name), set()).add((member, shape))
    result = {}
    for path, classes in sorted(members.items()):
        with open(path, encoding='utf-8') as h:
            text = h.read()
        bodies = class_bodies(text)
        insertions = []
        for class_name, added in classes.items():
            declarations = ' '.join(
                member_declaration(class_name, member, shape)
                for member, shape in sorted(added))
            # before the closing brace: the access of what the class
            # declares itself stays as it was
            insertions += [(end, f' public: {declarations} ')
                           for _, end in bodies.get(class_name, ())]
        for offset, insertion in sorted(insertions, reverse=True):
            text = text[:offset] + insertion + text[offset:]
        result[path] = _CATCH_ALLS_AHEAD + text
    return result


# The members name rsia_model's catch-alls, which a model header that
# rsia_model/message.h includes itself (boost/shared_ptr.hpp) has not
# seen: declared ahead, on the header's first line, a comment in every
# model header, so that its lines keep their numbers.
_CATCH_ALLS_AHEAD = (
    'namespace rsia_model { struct Any; struct Unknown; '
    'template <class RsiaClass> struct UnknownPointer; } ')
