# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What is declared already: by the package, the model, an alias."""

import re
import threading

from colcon_rsia.frontend.cpp.model_mode.headers import model_header_texts
from colcon_rsia.frontend.cpp.model_mode.model_index import declared_names
from colcon_rsia.frontend.cpp.model_mode.model_index import \
    model_headers_declaring
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import base_kind
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import CAMEL
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import CONSTANT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import FUNCTION
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import HEADER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import INCLUDES
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import LITERAL
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_KINDS
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_SCOPE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MEMBER_TYPE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import MODEL_MEMBER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NAMESPACE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NO_HASH
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import NO_OVERRIDE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import OBJECT
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import opened_namespaces
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import PRIORITY
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import SOURCE_NOISE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import STD_HEADER
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TEMPLATE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TEMPLATE_USE
from colcon_rsia.frontend.cpp.model_mode.recovery.kinds import TYPE


# the model's indexes are made once, by whichever unit asks first
_lock = threading.Lock()


def reopened_namespace(repair):
    """Whether a repair declares a lower-case namespace (harmless again).

    The package's own namespace (`autoware`) is undeclared where a header
    of a missing library names it first (`using
    autoware::kalman_filter::KalmanFilter;`); a class of the package is
    CamelCase, and stays the package's alone.
    """
    kind, name = repair
    return kind == NAMESPACE and not CAMEL.match(name.split('::')[-1])


_ALIAS_DEFINITION = re.compile(
    r'\bnamespace\s+(\w+)\s*=\s*(?:::\s*)?([A-Za-z_]\w*(?:\s*::\s*\w+)*)\s*;')


def aliases_of(texts):
    """{alias: namespace} of the `namespace bg = boost::geometry;` here."""
    return {match.group(1): re.sub(r'\s+', '', match.group(2))
            for text in texts for match in _ALIAS_DEFINITION.finditer(text)}


def unaliased(repairs, aliases):
    """Repairs of `bg::distance` as of `boost::geometry::distance`.

    `namespace bg = boost::geometry;` fails while boost::geometry is
    missing, and then so does every `bg::` after it: declaring a namespace
    bg would clash with the alias once its target exists.
    """
    if not aliases:
        return repairs
    result = set()
    for kind, name in repairs:
        head, _, rest = name.partition('::')
        if head in aliases and kind not in INCLUDES and \
                not kind.startswith('macro-'):
            name = aliases[head] + ('::' + rest if rest else '')
            if not rest:
                # the alias itself names its target, a namespace (clang
                # takes `pt` of `pt::ptree tree;` for an unknown type)
                kind = NAMESPACE
        result.add((kind, name))
    return result


# namespaces of the compiler's support library, which real headers bring
# in on the way (cxxabi.h through the C++ runtime's)
_SYSTEM_NAMESPACE_HEADER = {'abi': 'cxxabi.h'}


def included(repair, stand_in):
    """A name a model or stand-in header declares: include that header.

    A unit may use ``rclcpp::Duration`` or ``geometry_msgs::msg::Polygon``
    before it includes their header (through a header of an unknown
    library); a declaration of our own would then clash with the header's.
    """
    kind, name = repair
    if kind in INCLUDES or kind in MEMBER_KINDS + (TEMPLATE_USE,) or \
            kind.startswith(('macro-', MODEL_MEMBER)) or \
            kind in (NO_OVERRIDE, LITERAL, NO_HASH):
        return repair
    system_header = _SYSTEM_NAMESPACE_HEADER.get(name.split('::')[0])
    if system_header:
        # abi::__cxa_demangle: the compiler's own header has it
        return (STD_HEADER, system_header)
    header = model_header_for(name)
    if header is None and stand_in is not None:
        # (a header no stand-in holds yet is written with the repair:
        # see analysis._write_stand_ins_of_repair)
        header = interface_header(name)
    return (HEADER, header) if header else repair


_INTERFACE = re.compile(r'^(\w+)::(msg|srv|action)::([A-Z]\w*)$')


def interface_header(name):
    """``pkg/msg/pose_stamped.hpp`` of ``pkg::msg::PoseStamped``."""
    match = _INTERFACE.match(name)
    if not match:
        return None
    package, kind, type_name = match.groups()
    # rosidl's file names: GPSFix -> gps_fix, PoseStamped -> pose_stamped
    snake = re.sub(r'(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])', '_',
                   type_name).lower()
    return f'{package}/{kind}/{snake}.hpp'


def _rank(kind):
    # a template with values in its shape beats one without: its first
    # declaration may have come from a use the line did not show whole
    return (PRIORITY.index(base_kind(kind)), ':' not in kind)


def one_kind_each(repairs):
    """Keep one kind per name (a name both a type and an object is not).

    What was taken as declared inside a name that turns out a class
    becomes a member of that class.
    """
    chosen = {}
    for kind, name in sorted(repairs):
        if base_kind(kind) not in PRIORITY:
            chosen[(kind, name)] = (kind, name)
            continue
        current = chosen.get(name)
        if current is None or _rank(kind) < _rank(current[0]):
            chosen[name] = (kind, name)
    # `using ns::f;` (only a value to the line) and then `f(x)`, which
    # failed for it: ns::f is what the call needs, and a global f would
    # conflict with the using-declaration
    for kind, name in list(chosen.values()):
        short = name.rsplit('::', 1)[-1]
        used = chosen.get(short)
        if '::' in name and kind in (OBJECT, CONSTANT) and used and \
                used[0] in (FUNCTION, OBJECT, CONSTANT):
            chosen[name] = (used[0], name)
            del chosen[short]
        elif '::' in name and kind == FUNCTION and used and \
                used[0] == FUNCTION and \
                not CAMEL.match(name.split('::')[-2]):
            # (also when ns::f is a function already: the global f made
            # before `using ns::f;` took effect conflicts with it; not
            # beside a class's `QObject::connect`, where the unqualified
            # `connect(...)` of a derived class needs its own)
            del chosen[short]
    classes = {name for kind, name in chosen.values()
               if base_kind(kind) in (TYPE, TEMPLATE)}
    # a class the code also names qualified (`using ns::VehicleInfo;`, or a
    # `using namespace` seen before the namespace was declared) is that
    # class: a global one of the same name would make every use ambiguous
    qualified = {name.rsplit('::', 1)[1] for name in classes if '::' in name}
    # (and a member of it named through the short name is its member:
    # `Estimator::Direction` after `using ns::Estimator;`, unless the short
    # name was declared for itself: an rviz base class's method called
    # through its short name in a derived class resolves as repaired)
    full_name = {}
    for name in sorted(classes):
        if '::' in name:
            full_name.setdefault(name.rsplit('::', 1)[1], set()).add(name)
    result = set()
    for kind, name in chosen.values():
        owner = name.rsplit('::', 1)[0] if '::' in name else None
        if owner not in classes and owner not in chosen and \
                len(full_name.get(owner, ())) == 1:
            [owner] = full_name[owner]
            name = f'{owner}::{name.rsplit("::", 1)[1]}'
        if owner in classes and kind not in MEMBER_KINDS + INCLUDES:
            # (a scope inside a class, `Estimator::Direction::MAXIMIZE`,
            # is a nested type)
            kind = MEMBER_TYPE if base_kind(kind) in (
                TYPE, TEMPLATE, NAMESPACE) else MEMBER
        elif any(name.startswith(c + '::') for c in classes if c != owner):
            continue  # deeper inside a class: not declarable from outside
        elif owner is None and name in qualified and \
                base_kind(kind) in (TYPE, TEMPLATE):
            continue
        result.add((kind, name))
    # a member used as a type is a nested type, and one used as a scope
    # the class itself
    scopes = {name for kind, name in result if kind == MEMBER_SCOPE}
    return {(kind, name) for kind, name in result
            if kind == MEMBER_SCOPE or name not in scopes and (
                kind != MEMBER or (MEMBER_TYPE, name) not in result)}


def is_declared(name, declared):
    """Whether the package declares this name (in its own namespace)."""
    *namespaces, short = name.split('::')
    if short not in declared:
        return False
    # tf2::Transform is missing even if karto::Transform exists, and
    # autoware::trajectory::Trajectory even if the package's own
    # `using Trajectory = ...` in namespace autoware does: only namespaces
    # the package opens itself may hold its declaration
    return all(namespace in declared for namespace in namespaces)


_file_declarations = {}


def file_declarations(path, text):
    """declared_names of one file, read once per content.

    Every repair round of every unit asks for the names of the package's
    headers it includes: the same headers, the same text, again and again.
    """
    key = (path, len(text), hash(text))
    found = _file_declarations.get(key)
    if found is None:
        found = frozenset(declared_names([text]))
        with _lock:
            _file_declarations[key] = found
    return found


_ENUM_BODY = re.compile(r'\benum\s+(?!class\b|struct\b)\w*\s*(?::[^{;]*)?\{([^}]*)\}')
_global_enumerators = []  # [{enumerator: model header}], read once


def global_enumerator_header(name):
    """The model header whose global C enum has this enumerator, or None.

    `RCL_ROS_TIME` of rcl's `rcl_clock_type_t` (rclcpp/rclcpp.hpp), named
    before the unit includes the model: a constant of our own would clash
    with it.
    """
    texts = model_header_texts()
    with _lock:
        if not _global_enumerators:
            headers = {}
            for path, text in texts:
                code = SOURCE_NOISE.sub(' ', text)
                for match in _ENUM_BODY.finditer(code):
                    if opened_namespaces(code[:match.start()]):
                        continue
                    for enumerator in match.group(1).split(','):
                        word = enumerator.split('=')[0].strip()
                        if word:
                            headers.setdefault(word, path)
            _global_enumerators.append(headers)
        return _global_enumerators[0].get(name)


def model_header_for(name):
    """The model header (relative path) that declares a qualified name.

    One that opens the name's first namespace and declares its last part
    at namespace level (a class member of that name is another name);
    of several, the one in that namespace's directory, then the shortest.
    An unqualified name: the header of the global enum it is of.
    """
    *namespaces, short = name.split('::')
    if not namespaces:
        return global_enumerator_header(short)
    found = model_headers_declaring(name)
    if not found:
        return None
    return min(found, key=lambda p: (
        not p.startswith(namespaces[0] + '/'), len(p), p))
