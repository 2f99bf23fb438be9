# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The text of the stand-in for a missing include.

A message, service, action or dynamic_reconfigure config of a ROS 1
package or a ROS 2 interface gets the names and template shape its
generated header has; anything else is empty (with what the sources use of
its guessed namespace, declared when nothing else declares it).
"""

import os
import re

from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_NAMESPACES
from colcon_rsia.frontend.cpp.model_mode.model_index import \
    model_declares_class
from colcon_rsia.frontend.cpp.model_mode.model_index import model_declares_in
from colcon_rsia.frontend.cpp.model_mode.source_names import CAMEL
from colcon_rsia.frontend.cpp.model_mode.source_names import IDENTIFIER
from colcon_rsia.frontend.cpp.model_mode.source_names import member_ok
from colcon_rsia.frontend.cpp.model_mode.source_names import message_evidence
from colcon_rsia.frontend.cpp.model_mode.source_names import PACKAGE
from colcon_rsia.frontend.cpp.model_mode.source_names import service_evidence

# the version of the stand-ins' content: a stand-in of another version is
# written again
STUB_VERSION = 1
STUB_MARKER = f'// colcon-rsia stand-in v{STUB_VERSION}'


def empty_stub(name):
    """The stand-in of an include the model knows nothing of."""
    lines = [f'{STUB_MARKER} kind=empty: <{printable(name)}>',
             '// an include the model mode does not provide',
             '#pragma once']
    if _QT_HEADER.match(name):
        # every Qt header includes QtCore's (QObject, Q_OBJECT, the moc
        # keywords a class declaration of the unit's uses)
        lines.append('#include <rsia_model/qt_core.h>')
        lines += _qt_class(name)
    partial = partial_model(name)
    if partial:
        # what the model knows of the library, before what the sources
        # use of it is guessed (each declaration there skips its own)
        lines.append(f'#include <{partial}>')
    candidates = [guessed_namespace(name), nested_namespace(name)]
    for prefix, rest in prefix_namespaces(name):
        candidates += [prefix, f'{prefix}::{rest}']
    for namespace in candidates:
        if not namespace:
            continue
        # what the sources use of `namespace::`, if it is declared nowhere
        # else (prepare_model_arguments defines RSIA_MODEL_OWN_<ns> where it is)
        key = namespace_key(namespace)
        header = f'rsia_model/unknown/{key}.h'
        lines += [
            f'#if !defined(RSIA_MODEL_OWN_{key}) && '
            f'__has_include(<{header}>)',
            f'#include <{header}>',
            '#endif']
    return '\n'.join(lines) + '\n'


# the libraries the model knows a part of (rsia_model/partial/<top>.h): the
# facts' part, the rest being guessed as for any unknown library
PARTIAL_DIR = 'rsia_model/partial'


def partial_model(include):
    """The partial model header of an unknown include's library, or None."""
    top = include.split('/')[0]
    header = f'{PARTIAL_DIR}/{top}.h'
    if '/' in include and PACKAGE.match(top) and os.path.isfile(
            os.path.join(MODEL_HEADERS_DIR, *header.split('/'))):
        return header
    return None


# <QPushButton>, <QtWidgets/QWidget>, <QtGui/qpainter.h>
_QT_HEADER = re.compile(r'^Qt?[A-Z]\w*(?:/|$)')
# a Qt class header, named as the one class it declares: <QPushButton>,
# <QtWidgets/QWidget> (not a module's <QtGui>, nor <qpainter.h>)
_QT_CLASS_HEADER = re.compile(r'^(?:Qt\w+/)?(Q(?!t[A-Z])[A-Z]\w*)$')


def _qt_class(name):
    """The class a Qt class header declares, made from anything.

    An object of QObject (widgets are), unless the model has the class.
    """
    match = _QT_CLASS_HEADER.match(name)
    if match is None or model_declares_class(match.group(1)):
        return []
    qt_class = match.group(1)
    # (a repair header, force-included first, may have declared it)
    return ['#include <rsia_model/message.h>',
            f'#if !defined(RSIA_MODEL_QT_CLASS_{qt_class}) && '
            f'!defined({repaired_guard(qt_class)})',
            f'#define RSIA_MODEL_QT_CLASS_{qt_class}',
            f'struct {qt_class} : ::rsia_model::Unknown, QObject',
            '{', '  using ::rsia_model::Unknown::Unknown;',
            f'  {qt_class}() = default;', '};', '#endif']


# Qt's classes (QWidget, QPainter; not Q_OBJECT nor QT_VERSION), written
# without a qualifier, and the moc macros
_QT_NAME = re.compile(r'(?<![\w:])Q(?!t[A-Z])[A-Z][A-Z0-9]*[a-z]\w*\b')
_MOC_MACRO = re.compile(r'\bQ_(?:OBJECT|GADGET|SIGNALS|SLOTS|EMIT)\b')


def qt_used(codes, declared, includes):
    """The lines of a header declaring what the sources use of Qt, or [].

    A class of a library built on Qt (an rviz panel) uses Qt's classes and
    the moc macros without including Qt: the library's headers do. Only
    where the sources show Qt (a moc macro, an include of Qt).

    :param declared: a function of the names the sources declare
      themselves
    :param includes: the includes nothing provides
    """
    if not any(_MOC_MACRO.search(code) for code in codes) and \
            not any(_QT_HEADER.match(name) for name in includes):
        return []
    names = {name for code in codes for name in _QT_NAME.findall(code)}
    lines = ['#include <rsia_model/qt_core.h>']
    for name in sorted(names - declared()):
        lines += _qt_class(name)
    return lines


def guessed_namespace(include):
    """The namespace an unknown `dir/...` include probably declares.

    A library's top include directory is its namespace, by ROS convention
    for packages and for many libraries (`Eigen/Core`, `Poco/...`): only
    the names the sources use after `namespace::` are declared.
    """
    parts = include.split('/')
    if len(parts) < 2:
        return None
    return library_namespace(parts[0])


def library_namespace(name):
    """`name`, if an unknown library may declare a namespace so named."""
    if not IDENTIFIER.match(name) or name in MODEL_NAMESPACES or \
            name.endswith(('_msgs', '_srvs')) or not member_ok(name):
        return None
    return name


def nested_namespace(include):
    """The namespace `top::dir` of an unknown `top/dir/...` include, or None.

    Include directories mirror namespaces below the top one too
    (`boost/geometry/...`, `corp/planning_utils/...`). The nested guess
    serves where the top namespace is not guessed whole: a model library's
    (but for a name the model declares itself), or one the sources open
    themselves (the caller checks).
    """
    parts = include.split('/')
    if len(parts) < 3 or not PACKAGE.match(parts[1]) or \
            not member_ok(parts[1]) or not IDENTIFIER.match(parts[0]):
        return None
    top, name = parts[0], parts[1]
    if name in _ROS2_INTERFACE_DIRS:
        # a package's generated interfaces (a C header `pkg/msg/x.h`):
        # its `pkg::msg` namespace holds messages, which the stand-ins and
        # the implicit messages declare, and no library's names
        return None
    if not nested_in_model(top, name):
        return None
    return f'{top}::{name}'


def prefix_namespaces(include):
    """Where an unknown include's directory adds to its namespace's name.

    A library's directory often does (`dynamixel_sdk/` declares
    `dynamixel::`, `lanelet2_core/` `lanelet::`), and a package named
    `corp_planning_utils` of a stack whose namespace is `corp` may declare
    `corp::planning_utils::`. The caller keeps the splits the sources use.

    :returns: [(prefix, rest)], each split of the top directory at an
      underscore or before a version digit
    """
    top = include.split('/')[0]
    if '/' not in include or not PACKAGE.match(top):
        return []
    splits = []
    for boundary in re.finditer(r'(?=_)|(?<=[a-z])(?=\d)', top):
        prefix, rest = top[:boundary.start()], \
            top[boundary.start():].lstrip('_')
        if prefix and member_ok(prefix) and rest:
            splits.append((prefix, rest))
    return splits


def nested_in_model(top, name):
    """Whether `top::name` is a namespace the sources may fill in.

    (Not a name the model declares in `top` itself.)
    """
    return IDENTIFIER.match(name) is not None and member_ok(name) and not (
        top in MODEL_NAMESPACES and model_declares_in(top, name))


def namespace_key(namespace):
    """A qualified namespace as a file and macro name (`a__b`)."""
    return namespace.replace('::', '__')


def repaired_guard(qualified_name):
    """The macro defined with a catch-all declaration of a name.

    A repair header, a partial model or a stand-in of an unknown library
    defines it; any later declaration of the name steps aside.
    """
    return '__'.join(['RSIA_REPAIRED'] + qualified_name.split('::'))


def printable(text):
    """Text for a comment of a generated header: ASCII only."""
    return text.encode('ascii', 'replace').decode('ascii')


def stand_ins_for(include, codes, message=False):
    """{include name: content} of the stand-in(s) for one include.

    :param message: whether a `pkg/Name.h` is known to be a message's
      header (a model header includes it, or it is part of a message)
    """
    parts = include.split('/')
    if len(parts) == 3 and parts[1] in _ROS2_INTERFACE_DIRS and \
            parts[2].endswith('.hpp') and PACKAGE.match(parts[0]):
        return {include: _ros2_interface_stub(*parts, codes)}
    if len(parts) != 2 or not parts[1].endswith('.h'):
        return {include: empty_stub(include)}
    package, name = parts[0], parts[1][:-2]
    # messages are CamelCase, with exceptions (tf/tfMessage.h): a header
    # whose stem the sources name as `package::stem` is one too, unless
    # only ever called (fmt/format.h and fmt::format(...)) or given
    # template arguments, which a message's typedef takes none of
    # (thrust/device_vector.h and thrust::device_vector<T>)
    named = IDENTIFIER.match(name) and any(
        re.search(r'\b' + re.escape(package) + r'\s*::\s*' + name +
                  r'\b(?!\s*[(<])',
                  code)
        for code in codes)

    def in_namespace():
        # ... and a library's header named after its class
        # (lanelet2_core/LaneletMap.h) looks like one: a message (or a
        # dynamic_reconfigure config) is in its package's namespace, which
        # the code then names, uses or opens (or in a package named as
        # interface packages are). (Searched only where it decides.)
        return message or package.endswith(('_msgs', '_srvs')) or any(
            re.search(r'(?<![\w:])' + re.escape(package) + r'\s*::', code)
            or re.search(r'\bnamespace\s+' + re.escape(package) + r'\b',
                         code)
            for code in codes)
    if not (PACKAGE.match(package) and (
            named or (CAMEL.match(name) and in_namespace()))):
        return {include: empty_stub(include)}
    for suffix, member in (('ActionGoal', 'goal'), ('ActionResult', 'result'),
                           ('ActionFeedback', 'feedback')):
        if name.endswith(suffix) and len(name) > len(suffix):
            base = name[:-len(suffix)]
            inner = base + suffix[len('Action'):]
            stubs = stand_ins_for(f'{package}/{inner}.h', codes, True)
            stubs[include] = _message_stub(
                package, name, includes=[f'{package}/{inner}.h'],
                typedefs=[(f'_{member}_type', f'{inner}_<ContainerAllocator>')])
            return stubs
    if name.endswith('Action') and len(name) > len('Action'):
        base = name[:-len('Action')]
        stubs = {}
        typedefs = []
        includes = []
        for part, member in (('Goal', 'goal'), ('Result', 'result'),
                             ('Feedback', 'feedback')):
            sub = f'{package}/{base}Action{part}.h'
            stubs.update(stand_ins_for(sub, codes, True))
            includes.append(sub)
            typedefs.append((f'_action_{member}_type',
                             f'{base}Action{part}_<ContainerAllocator>'))
        stubs[include] = _message_stub(
            package, name, includes=includes, typedefs=typedefs)
        return stubs
    if name.endswith('Config') and len(name) > len('Config') and \
            not message_evidence(name, codes):
        return {include: _config_stub(package, name)}
    if service_evidence(name, codes) and \
            not name.endswith(('Request', 'Response')):
        stubs = {}
        for part in ('Request', 'Response'):
            stubs.update(stand_ins_for(f'{package}/{name}{part}.h', codes, True))
        if message_evidence(name, codes):
            stubs[include] = _combined_stub(package, name)
        else:
            stubs[include] = _service_stub(package, name)
        return stubs
    # nothing tells a message from a service used only generically
    # (`typename S::Request`): a message also names the would-be parts
    return {include: _message_stub(
        package, name,
        declarations=[
            'template <class ContainerAllocator>',
            f'struct {name}Request_;',
            'template <class ContainerAllocator>',
            f'struct {name}Response_;', ''],
        typedefs=[('Request', f'{name}Request_<ContainerAllocator>'),
                  ('Response', f'{name}Response_<ContainerAllocator>')])}


# ROS 2 interfaces: `<pkg/msg/laser_scan.hpp>` declares
# `pkg::msg::LaserScan_<ContainerAllocator>` and `pkg::msg::LaserScan`
_ROS2_INTERFACE_DIRS = frozenset({'msg', 'srv', 'action'})


def _ros2_type_names(package, kind, file_stem, codes):
    """The CamelCase names a snake_case interface header declares.

    Every spelling the sources use (``uuid.hpp`` declares ``UUID``), else
    the one made from the file name.
    """
    wanted = file_stem.replace('_', '').lower()
    pattern = re.compile(
        r'\b' + re.escape(package) + r'\s*::\s*' + kind +
        r'\s*::\s*([A-Z]\w*)')
    names = {match.group(1) for code in codes
             for match in pattern.finditer(code)
             if match.group(1).lower() == wanted}
    return sorted(names) or [
        ''.join(p[:1].upper() + p[1:] for p in file_stem.split('_'))]


def _ros2_interface_stub(package, kind, file_name, codes):
    stem = file_name[:-len('.hpp')]
    if '__' in stem or not PACKAGE.match(stem):
        return empty_stub(f'{package}/{kind}/{file_name}')
    return ros2_interface_text(
        package, kind, file_name, _ros2_type_names(package, kind, stem, codes))


# the names a ROS 2 interface's stand-in declares, on its second line: the
# units of a package may spell one differently (or not at all), and each
# unit's stand-in keeps what the others needed
_DECLARES = '// declares: '


def ros2_interface_text(package, kind, file_name, names):
    """The stand-in of ``<package/kind/file_name>`` declaring `names`."""
    stem = file_name[:-len('.hpp')]
    guard = f'RSIA_STUB_{package}_{kind}_{stem}_HPP'
    lines = [
        f'{STUB_MARKER} kind=ros2_{kind}: <{package}/{kind}/{file_name}>',
        _DECLARES + ' '.join(names),
        '// a ROS 2 interface the model mode cannot read: the name, template',
        '// shape and pointer aliases of a generated rosidl header, its fields',
        '// the catch-all rsia_model::Fields',
        f'#ifndef {guard}', f'#define {guard}', '',
        '#include <memory>', '#include <rsia_model/message.h>', '',
        f'namespace {package}', '{', f'namespace {kind}', '{', '']

    def struct(struct_name):
        return [
            'template <class ContainerAllocator>',
            f'struct {struct_name}_ : ::rsia_model::Fields',
            '{',
            f'  using Type = {struct_name}_<ContainerAllocator>;',
            f'  using SharedPtr = std::shared_ptr<{struct_name}_>;',
            f'  using ConstSharedPtr = std::shared_ptr<const {struct_name}_>;',
            f'  using UniquePtr = std::unique_ptr<{struct_name}_>;',
            f'  using ConstUniquePtr = std::unique_ptr<const {struct_name}_>;',
            f'  using WeakPtr = std::weak_ptr<{struct_name}_>;',
            f'  using ConstWeakPtr = std::weak_ptr<const {struct_name}_>;',
            '  // (deprecated in rosidl, as in ROS 1)',
            '  using Ptr = SharedPtr;',
            '  using ConstPtr = ConstSharedPtr;',
            '  // rosidl compares two messages of a type field by field',
            f'  bool operator==(const {struct_name}_&) const;',
            f'  bool operator!=(const {struct_name}_&) const;',
            '};',
            f'using {struct_name} = {struct_name}_<std::allocator<void>>;', '']
    for name in names:
        if kind == 'msg':
            lines += struct(name)
        elif kind == 'srv':
            lines += struct(name + '_Request') + struct(name + '_Response')
            lines += [f'struct {name}', '{',
                      f'  using Request = {name}_Request;',
                      f'  using Response = {name}_Response;', '};', '']
        else:
            parts = ('Goal', 'Result', 'Feedback')
            for part in parts:
                lines += struct(f'{name}_{part}')
            lines += [f'struct {name}', '{']
            lines += [f'  using {part} = {name}_{part};' for part in parts]
            lines += ['};', '']
    lines += [f'}}  // namespace {kind}', f'}}  // namespace {package}', '',
              f'#endif  // {guard}', '']
    return '\n'.join(lines)


def merged_ros2_interface(existing, content):
    """One ROS 2 interface stand-in declaring the names of both, or None.

    None when they are not two stand-ins of the same ROS 2 interface.
    """
    def parts(text):
        head = text.split('\n', 2)
        match = re.match(
            re.escape(STUB_MARKER) + r' kind=ros2_\w+: <(\w+)/(\w+)/(\w+\.hpp)>$',
            head[0])
        if not match or len(head) < 2 or not head[1].startswith(_DECLARES):
            return None
        return match.groups(), head[1][len(_DECLARES):].split()
    old, new = parts(existing), parts(content)
    if old is None or new is None or old[0] != new[0]:
        return None
    return ros2_interface_text(*old[0], sorted(set(old[1]) | set(new[1])))


def _guard(package, name):
    return f'RSIA_STUB_{package}_{name}_H'


def _guarded_header(package, name, kind, about, includes, body):
    """A stand-in's text: its marker, guard and namespace around `body`."""
    guard = _guard(package, name)
    return '\n'.join([
        f'{STUB_MARKER} kind={kind}: <{package}/{name}.h>', *about,
        f'#ifndef {guard}', f'#define {guard}', '', *includes, '',
        f'namespace {package}', '{', '', *body, '',
        f'}}  // namespace {package}', '', f'#endif  // {guard}', ''])


def _message_stub(package, name, *, includes=(), typedefs=(), kind='message',
                  declarations=()):
    body = list(declarations) + [
        'template <class ContainerAllocator>',
        f'struct {name}_ : ::rsia_model::Fields',
        '{',
        f'  typedef {name}_<ContainerAllocator> Type;']
    body += [f'  typedef {target} {alias};' for alias, target in typedefs]
    body += [
        f'  typedef boost::shared_ptr<{name}_<ContainerAllocator>> Ptr;',
        f'  typedef boost::shared_ptr<{name}_<ContainerAllocator> const> '
        'ConstPtr;',
        '  // gencpp compares two messages of a type field by field',
        f'  bool operator==(const {name}_&) const;',
        f'  bool operator!=(const {name}_&) const;',
        '};',
        '',
        f'typedef ::{package}::{name}_<std::allocator<void>> {name};',
        f'typedef boost::shared_ptr< ::{package}::{name}> {name}Ptr;',
        f'typedef boost::shared_ptr< ::{package}::{name} const> '
        f'{name}ConstPtr;']
    return _guarded_header(
        package, name, kind,
        ['// a message the model mode cannot read: its name, template shape and',
         '// pointer typedefs are those of a generated message header, its',
         '// fields the catch-all rsia_model::Fields'],
        # (as a generated header: the traits code specialises to make its
        # own types messages)
        ['#include <rsia_model/message.h>', '#include <ros/message_traits.h>',
         '#include <ros/serialization.h>',
         '#include <ros/message_operations.h>'] +
        [f'#include <{i}>' for i in includes], body)


def _service_stub(package, name):
    return _guarded_header(
        package, name, 'service',
        ['// a service the model mode cannot read (the sources use its Request',
         '// or Response): the struct of a generated service header'],
        [f'#include <{package}/{name}Request.h>',
         f'#include <{package}/{name}Response.h>'],
        [f'struct {name}',
         '{',
         f'  typedef {name}Request Request;',
         f'  typedef {name}Response Response;',
         '  Request request;',
         '  Response response;',
         '  typedef Request RequestType;',
         '  typedef Response ResponseType;',
         '};'])


def _combined_stub(package, name):
    """A name used both as a message and as a service: serve both."""
    return _message_stub(
        package, name, kind='service_message',
        includes=[f'{package}/{name}Request.h', f'{package}/{name}Response.h'],
        typedefs=[('Request', f'::{package}::{name}Request'),
                  ('Response', f'::{package}::{name}Response'),
                  ('RequestType', f'::{package}::{name}Request'),
                  ('ResponseType', f'::{package}::{name}Response')])


def combined_stub_from(content):
    """A message's stand-in made one of a service too (see _combined_stub)."""
    match = re.search(r'<(\w+)/(\w+)\.h>', content.split('\n', 1)[0])
    return _combined_stub(match.group(1), match.group(2)) if match \
        else content


def _config_stub(package, name):
    return _guarded_header(
        package, name, 'config',
        ['// a dynamic_reconfigure config (generated from a .cfg file): its',
         '// parameters are the catch-all rsia_model::Fields'],
        ['#include <rsia_model/message.h>'],
        [f'class {name} : public ::rsia_model::Fields',
         '{',
         'public:',
         f'  static const {name}& __getDefault__();',
         f'  static const {name}& __getMin__();',
         f'  static const {name}& __getMax__();',
         '};'])
