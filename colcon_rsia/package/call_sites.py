# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The ROS call sites a package's source text shows, found without parsing.

The yardstick of coverage: a reader counting ``advertise<``,
``create_subscription<``, ``rospy.Publisher(`` ... in the package's own
files (tests aside) finds these call sites; each one the analysis turned
into a fact is understood, each other one is a blind spot. The scan is
deliberately independent of the front ends (text for C++, Python's ``ast``
for Python), so that a front end cannot hide what it missed.

Only the calls that *create* a publisher or a subscription are counted:
they are the edges of the rate graph.
"""

import ast
from dataclasses import dataclass
import os
import re

from colcon_rsia import safe_files

PUBLISHER = 'publisher'
SUBSCRIBER = 'subscriber'

CXX_SOURCE_EXTENSIONS = ('.cpp', '.cc', '.cxx', '.c++', '.C')
CXX_HEADER_EXTENSIONS = ('.h', '.hh', '.hpp', '.hxx', '.h++', '.ipp')
# directories whose files are never a node's (tests, build output, docs)
SKIPPED_DIRECTORIES = frozenset({
    'test', 'tests', 'build', 'install', 'devel', 'log', 'CMakeFiles',
    'doc', 'docs'})

# C++: the method (or free function) names that create an endpoint. A
# call is the name followed by `<` or `(` and preceded by an object
# (`.`, `->`, `::`) or by the start of an expression; a declaration of a
# function with that name (`SharedPtr create_publisher(`) is preceded by
# a type and does not count.
_CXX_CALLS = {
    'advertise': PUBLISHER,
    'advertiseCamera': PUBLISHER,
    'create_publisher': PUBLISHER,
    'create_generic_publisher': PUBLISHER,
    'create_camera_publisher': PUBLISHER,
    'subscribe': SUBSCRIBER,
    'subscribeCamera': SUBSCRIBER,
    'create_subscription': SUBSCRIBER,
    'create_generic_subscription': SUBSCRIBER,
    'create_camera_subscription': SUBSCRIBER,
}
_CXX_CALL = re.compile(
    r'\b(?P<name>' + '|'.join(sorted(_CXX_CALLS, key=len, reverse=True)) +
    r')\s*[<(]')
# what may come before a call's name: a member access, an operator or a
# punctuator, `return`/`template`, or the start of a line
_CALL_CONTEXT = re.compile(r'(?:[.:>=(,{;!&|?]|\breturn|\btemplate)$')
_LOOK_BACK = 200
_CXX_COMMENT_OR_LITERAL = re.compile(
    r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
    re.DOTALL)
_PREPROCESSOR_LINE = re.compile(r'^[ \t]*#[^\n]*(?:\\\n[^\n]*)*', re.MULTILINE)
# C++: class templates whose construction with a node and a topic creates
# an endpoint: `RealtimePublisher<M>(nh, "topic", 4)` (ROS 1; the ROS 2
# wrapper of an existing publisher takes one argument and creates none),
# `message_filters::Subscriber<M> sub(nh, "topic", 1)`
_CXX_CONSTRUCTED = {
    'RealtimePublisher': PUBLISHER,
    'Subscriber': SUBSCRIBER,
    'SubscriberFilter': SUBSCRIBER,
}
_CXX_CONSTRUCTION = re.compile(
    r'(?P<name>\b(?:realtime_tools\s*::\s*RealtimePublisher|'
    r'message_filters\s*::\s*Subscriber|'
    r'image_transport\s*::\s*SubscriberFilter))\s*<')

# Python: rospy's classes and rclpy's methods
_PYTHON_CLASSES = {'Publisher': PUBLISHER, 'Subscriber': SUBSCRIBER}
_PYTHON_CLASS_MODULES = frozenset({'rospy', 'message_filters'})
_PYTHON_METHODS = {
    'create_publisher': PUBLISHER,
    'create_subscription': SUBSCRIBER,
}


@dataclass(frozen=True)
class CallSite:
    """One call that creates a publisher or subscription."""

    file: str      # relative to the package
    line: int
    role: str      # PUBLISHER | SUBSCRIBER
    api: str       # the name called


def _blank(match):
    """A comment or literal replaced by spaces, keeping its newlines."""
    text = match.group(0)
    return re.sub(r'[^\n]', ' ', text)


# the qualification of a name: `A::B::` (template arguments end it)
_QUALIFIER = re.compile(r'(?:\b\w+\s*::\s*)+$')
# what leaves the call without an object: not `.`, `->` or `Type::`
_OBJECT_ACCESS = re.compile(r'(?:\.|->|::)$')
# the last scope of a qualified call: `T::` in `T::subscribe(`
_LAST_SCOPE = re.compile(r'\b(\w+)\s*::$')
# a template's parameter list (one level of nested `<>`), and the type
# parameters it declares: `template <typename T, class U = X<int>>`
_TEMPLATE_PARAMETERS = re.compile(r'\btemplate\s*<((?:[^<>]|<[^<>]*>)*)>')
_TYPE_PARAMETER = re.compile(r'\b(?:typename|class)\s+(\w+)')


def cxx_call_sites(text, own_functions=frozenset()):
    """Return [(line, role, name)] of the endpoint calls in C++ text.

    :param own_functions: names of the list that the package defines
      itself: a call of one without an object (``subscribe(name);`` in a
      method of the class) calls the package's function, not ROS
    """
    return _cxx_scan(text, own_functions)[0]


def cxx_own_functions(text):
    """The names of the list that C++ text declares or defines."""
    return _cxx_scan(text, frozenset())[1]


def _cxx_scan(text, own_functions):
    code = _CXX_COMMENT_OR_LITERAL.sub(_blank, text)
    # `#define X nh.advertise<...>`: a macro's body is no call site
    code = _PREPROCESSOR_LINE.sub(_blank, code)
    # a call qualified by a template's type parameter (`T::subscribe(hz)`)
    # calls a static member of the type given: ROS's endpoint methods are
    # members called on a handle, its endpoint functions are in namespaces
    type_parameters = {
        parameter for parameters in _TEMPLATE_PARAMETERS.finditer(code)
        for parameter in _TYPE_PARAMETER.findall(parameters.group(1))}
    sites = []
    declared = set()
    for match in _CXX_CALL.finditer(code):
        start = match.start('name')
        name = match.group('name')
        before = code[max(0, start - _LOOK_BACK):start]
        stripped = before.rstrip()
        # a definition `void ns::Class::subscribe(` or
        # `std::shared_ptr<P> Class::create_publisher(`: a type before the
        # qualified name
        unqualified = _QUALIFIER.sub('', stripped).rstrip()
        qualified = unqualified != stripped
        # (checked here, not in the pattern: a pattern that first skips
        # whitespace is quadratic in the long blank runs left by comments)
        if stripped and '\n' not in before[len(stripped):] and \
                not _CALL_CONTEXT.search(stripped) or qualified and (
                    unqualified[-1:].isalnum() or unqualified[-1:] in '_*&'
                    or unqualified.endswith('>') and
                    not unqualified.endswith('->')):
            declared.add(name)
            continue
        if name in own_functions and not _OBJECT_ACCESS.search(stripped) \
                or stripped.endswith('this->') and name in own_functions:
            continue
        scope = _LAST_SCOPE.search(stripped)
        if scope and scope.group(1) in type_parameters:
            continue
        # (the text, where the literals an argument may be are not blanked)
        if _without_arguments(text, match.end() - 1):
            continue
        line = code.count('\n', 0, start) + 1
        sites.append((line, _CXX_CALLS[name], name))
    for match in _CXX_CONSTRUCTION.finditer(code):
        if _constructed_with_arguments(code, match.end()):
            name = re.sub(r'\s+', '', match.group('name'))
            line = code.count('\n', 0, match.start('name')) + 1
            sites.append((line, _CXX_CONSTRUCTED[name.split('::')[-1]], name))
    return sorted(sites), declared


def _without_arguments(code, position):
    """Whether the call whose ``<`` or ``(`` is at `position` passes none.

    Every call that creates an endpoint passes at least its topic (or the
    options holding it): ``subscribe()``, a display's or a filter's
    re-subscription to the topic it already has, creates none.
    """
    i = position
    if code[i] == '<':
        depth = 0
        while i < len(code):
            depth += {'<': 1, '>': -1}.get(code[i], 0)
            i += 1
            if depth == 0:
                break
        match = re.compile(r'\s*\(').match(code, i)
        if match is None:
            return False
        i = match.end() - 1
    return re.compile(r'\(\s*\)').match(code, i) is not None


def _constructed_with_arguments(code, position):
    """Whether `<...>` at `position` is followed by a call of 2+ arguments.

    ``T<A, B> name(x, y)`` and ``T<A>(x, y)`` are; a type in a declaration
    (``std::shared_ptr<T<A>> p_;``) or a one-argument wrapper is not.
    """
    depth = 1
    i = position
    while i < len(code) and depth:
        depth += {'<': 1, '>': -1}.get(code[i], 0)
        i += 1
    match = re.compile(r'\s*(?:\w+\s*)?\(').match(code, i)
    if depth or match is None:
        return False
    depth = 1
    i = match.end()
    while i < len(code) and depth:
        ch = code[i]
        if ch in '([{':
            depth += 1
        elif ch in ')]}':
            depth -= 1
        elif ch == ',' and depth == 1:
            return True
        elif ch == ';':
            return False
        i += 1
    return False


def python_call_sites(text):
    """Return [(line, role, name)] of the endpoint calls in Python text.

    ``rospy.Publisher(...)``, ``Publisher(...)`` imported from rospy,
    ``message_filters.Subscriber(...)``, ``x.create_publisher(...)``.
    """
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return []
    imported = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and \
                node.module in _PYTHON_CLASS_MODULES:
            imported |= {alias.asname or alias.name for alias in node.names
                         if alias.name in _PYTHON_CLASSES}
    sites = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        if isinstance(func, ast.Attribute):
            if func.attr in _PYTHON_METHODS:
                sites.append((node.lineno, _PYTHON_METHODS[func.attr],
                              func.attr))
            elif func.attr in _PYTHON_CLASSES and \
                    isinstance(func.value, ast.Name) and \
                    func.value.id in _PYTHON_CLASS_MODULES:
                sites.append((node.lineno, _PYTHON_CLASSES[func.attr],
                              f'{func.value.id}.{func.attr}'))
        elif isinstance(func, ast.Name) and func.id in imported:
            sites.append((node.lineno, _PYTHON_CLASSES.get(
                func.id, PUBLISHER), func.id))
    return sorted(sites)


def _is_python_file(path):
    if path.endswith('.py'):
        return not path.endswith(('.launch.py', 'setup.py'))
    if os.path.splitext(path)[1]:
        return False
    try:
        first = safe_files.read_head(path, 200).split(b'\n', 1)[0]
    except OSError:
        return False
    return first.startswith(b'#!') and b'python' in first


def package_files(package_path):
    """The package's own code files (tests, build output, launch aside)."""
    files = []
    for root, dirs, names in os.walk(package_path):
        dirs[:] = sorted(
            d for d in dirs
            if d not in SKIPPED_DIRECTORIES and not d.startswith('.') and
            d != 'launch' and
            not os.path.exists(os.path.join(root, d, 'package.xml')))
        for name in sorted(names):
            files.append(os.path.join(root, name))
    return files


def scan_package(package_path):
    """Every endpoint call site in the package's own files.

    :rtype: list of :class:`CallSite`, sorted by file and line
    """
    texts = {}
    for path in package_files(package_path):
        if not os.path.isfile(path) or os.path.islink(path):
            continue
        if not path.endswith(CXX_SOURCE_EXTENSIONS + CXX_HEADER_EXTENSIONS) \
                and not _is_python_file(path):
            continue
        try:
            # the analysis's own checks and size limit: a file it did not
            # read is not counted either (it names the file)
            texts[path] = safe_files.read_text(
                path, roots=[package_path], errors='replace')
        except OSError:
            continue
    cxx = {p: t for p, t in texts.items()
           if p.endswith(CXX_SOURCE_EXTENSIONS + CXX_HEADER_EXTENSIONS)}
    # the package's own `subscribe()`, `create_publisher()` ...: calls of
    # them are the package's calls (its ROS calls are counted inside)
    own = set()
    for text in cxx.values():
        own |= cxx_own_functions(text)
    sites = []
    for path, text in sorted(texts.items()):
        found = cxx_call_sites(text, own) if path in cxx \
            else python_call_sites(text)
        relative = os.path.relpath(path, package_path)
        sites += [CallSite(relative, line, role, api)
                  for line, role, api in found]
    return sorted(sites, key=lambda s: (s.file, s.line, s.role))
