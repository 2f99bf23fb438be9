# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What every launch front end shares: files, packages, XML, YAML, names."""

from dataclasses import dataclass
from dataclasses import field
import glob
import os
import re
from typing import Dict
from typing import List

from colcon_rsia import safe_files
from colcon_rsia.launch.model import LaunchError
from colcon_rsia.launch.model import LaunchResult
from colcon_rsia.launch.notes import shorten
from colcon_rsia.launch.safe_eval import Unresolved
from defusedxml import DefusedXmlException
from defusedxml.ElementTree import DefusedXMLParser
from defusedxml.ElementTree import ParseError
import yaml

# a launch or parameter file larger than this is not a hand-written file
# (the largest real ones are some hundred KiB)
MAX_FILE_SIZE = 8 * 1024 * 1024
# includes nested deeper than this are runaway recursion, not a system
# (real systems nest a handful of levels)
MAX_INCLUDE_DEPTH = 32
# includes read in one load: a file that includes the next one twice, 30
# levels deep, must not make 2**30 reads (the largest real systems read a
# few hundred files)
MAX_INCLUDES = 2000
# parameters one YAML value may expand to: YAML aliases can nest a
# billion, the largest real parameter files hold a few thousand
MAX_PARAMETERS = 20000
# values one YAML file may hold, as written (MAX_PARAMETERS * 10, the
# budget of check_value): counted before the file is loaded, which takes
# PyYAML some 40 s and 700 MB for a quarter million
MAX_YAML_VALUES = MAX_PARAMETERS * 10
# THE nesting limit of launch elements, for every reader (ROS 1 XML,
# ROS 2 XML and YAML) and the ROS 2 executor (groups and the includes
# they contain), and of YAML values: all are handled recursively. Real
# files nest a handful of levels; at a few Python frames a level, 64
# keeps the stack well below its limit of 1000. Other nestings have their
# own: includes (MAX_INCLUDE_DEPTH), substitutions
# (substitutions.MAX_SUBSTITUTION_NESTING), values in values
# (ros2_values.MAX_VALUE_DEPTH), Python launch code
# (python_launch_values.MAX_CODE_NESTING)
MAX_NESTING = 64
# node name patterns of parameter files longer than this, or with more
# wildcards, match nothing (their regular expression could backtrack for
# long)
MAX_PATTERN_LENGTH = 256
MAX_PATTERN_WILDCARDS = 8
# where installed packages are looked for when not in the workspace
INSTALLED_SHARE_PATTERNS = ('/opt/ros/*/share/{}', '/usr/share/{}')


@dataclass
class UnknownArg:
    """An argument (launch configuration) not known statically."""

    reason: str


@dataclass
class Elem:
    """An element of an XML or YAML launch file."""

    tag: str
    attrs: Dict[str, object]
    children: List['Elem'] = field(default_factory=list)
    text: str = ''
    line: int = 0


class Loader:
    """The state of one :func:`load_launch` call, shared by the front ends."""

    def __init__(self, *, arguments, package_paths, environ):  # noqa: D107
        self.arguments = {str(k): str(v) for k, v in (arguments or {}).items()}
        self.package_paths = {
            str(k): os.path.abspath(os.fspath(v))
            for k, v in (package_paths or {}).items()}
        self.environ = dict(os.environ if environ is None else environ)
        self.result = LaunchResult()
        self.include_stack = []  # real paths of the files being read
        self.includes = 0
        self.actions = 0         # ROS 2 actions executed
        self.python_steps = 0    # Python launch code interpreted

    def note(self, text):
        """Record a file-level note, once."""
        if text not in self.result.unresolved:
            self.result.unresolved.append(text)

    def read_text(self, path):
        """The text of a launch or parameter file; recorded in ``files``."""
        try:
            size = os.path.getsize(path)
            if size > MAX_FILE_SIZE:
                raise LaunchError(
                    f'{path}: the file is too large to be a launch or '
                    f'parameter file ({size} bytes).')
            # checked: a FIFO or a link to /dev/zero must not hang us
            data = safe_files.read_bytes(path, limit=MAX_FILE_SIZE)
        except safe_files.UnsafeFileError as e:
            raise LaunchError(f'{path}: {e}.')
        except OSError as e:
            raise LaunchError(f'{path}: cannot be read ({e.strerror}).')
        if str(path) not in self.result.files:
            self.result.files.append(str(path))
        try:
            return data.decode('utf-8')
        except UnicodeDecodeError:
            raise LaunchError(f'{path}: is not UTF-8 text.')

    def read_launch(self, path):
        """A launch file's text, parsed XML (None for Python, YAML) and kind.

        :raises LaunchError: when it cannot be read, or is malformed XML
        """
        text = self.read_text(path)
        root = None
        if not path.lower().endswith(('.py', '.yaml', '.yml')):
            root = parse_xml(text, path)
        return text, root, file_kind(path, text, root)

    def find_package(self, package, kind):
        """The directory of a package for ``$(find)`` and its relatives.

        :param str kind: 'find' (ROS 1 source or share directory), 'share'
          or 'prefix' (ROS 2)
        :raises Unresolved: when the package is not known
        """
        if not package or '/' in package or package in ('.', '..'):
            raise Unresolved(f"'{package}' is not a package name")
        if package in self.package_paths:
            if kind == 'prefix':
                raise Unresolved(
                    f'the install prefix of workspace package {package} is '
                    'not known before it is installed')
            return self.package_paths[package]
        for pattern in INSTALLED_SHARE_PATTERNS:
            matches = sorted(glob.glob(pattern.format(glob.escape(package))))
            matches = [m for m in matches if os.path.isdir(m)]
            if matches:
                share = matches[-1]
                if kind == 'prefix':
                    return os.path.dirname(os.path.dirname(share))
                return share
        raise Unresolved(f'package {package} was not found')

    def enter_include(self, path, location):
        """Start reading an included file; False (with a note) to skip it."""
        if not os.path.isfile(path):
            self.note(f'{location}: included file {path} not found')
            return False
        real = os.path.realpath(path)
        if real in self.include_stack:
            self.note(f'{location}: include cycle: {path} is already being '
                      'read; not included again')
            return False
        if len(self.include_stack) >= MAX_INCLUDE_DEPTH:
            self.note(f'{location}: includes nested deeper than '
                      f'{MAX_INCLUDE_DEPTH} levels; {path} not included')
            return False
        if self.includes >= MAX_INCLUDES:
            self.note(f'{location}: more than {MAX_INCLUDES} includes; '
                      f'{path} not included')
            return False
        self.includes += 1
        self.include_stack.append(real)
        return True

    def leave_include(self):
        """Done reading the last entered file."""
        self.include_stack.pop()


def argument_text(arguments, name, *, declaring=None, missing='is not set'):
    """The text of a launch argument (``$(arg)``, ``$(var)``).

    :param dict arguments: name -> text or :class:`UnknownArg`
    :param declaring: the argument whose default is being read (it may
      not refer to itself)
    :param str missing: how a note says that the argument has no value
    :raises Unresolved: when its value is not known statically
    """
    if name == declaring:
        raise Unresolved(f"argument '{name}' refers to itself")
    if name not in arguments:
        raise Unresolved(f"argument '{name}' {missing}")
    value = arguments[name]
    if isinstance(value, UnknownArg):
        raise Unresolved(f"argument '{name}' is not known: {value.reason}")
    return value


def location(path, line):
    """'path:line' of an element."""
    return f'{path}:{line}'


# XML


class _XmlBuilder:
    """ElementTree parser target building :class:`Elem` with line numbers."""

    def __init__(self):
        self.parser = None
        self.stack = []
        self.root = None

    def start(self, tag, attrib):
        line = self.parser.parser.CurrentLineNumber
        elem = Elem(_local(tag), {_local(k): v for k, v in attrib.items()},
                    line=line)
        if self.stack:
            self.stack[-1].children.append(elem)
        else:
            self.root = elem
        self.stack.append(elem)

    def end(self, tag):
        self.stack.pop()

    def data(self, data):
        if self.stack:
            self.stack[-1].text += data

    def close(self):
        return self.root


def _local(tag):
    return tag.rsplit('}', 1)[-1] if tag.startswith('{') else tag


def parse_xml(text, path):
    """Parse XML text with defusedxml into :class:`Elem` (with lines).

    :raises LaunchError: for malformed XML and refused DTD entities
    """
    builder = _XmlBuilder()
    parser = DefusedXMLParser(target=builder)
    builder.parser = parser
    try:
        parser.feed(text)
        root = parser.close()
    except DefusedXmlException as e:
        raise LaunchError(
            f'{path}: refused to read the XML because it declares entities '
            f'or external references ({type(e).__name__}).')
    except ParseError as e:
        raise LaunchError(f'{path}: malformed XML ({e}).')
    except (RecursionError, MemoryError):
        raise LaunchError(f'{path}: the XML is nested too deeply.')
    if root is None:
        raise LaunchError(f'{path}: the XML has no root element.')
    return root


# YAML


def load_yaml(text, path):
    """``yaml.safe_load`` of a file's text.

    :raises LaunchError: for malformed YAML
    :raises Unresolved: for YAML tags safe_load does not accept (such as
      ROS 1's ``!degrees``)
    """
    try:
        _count_values(text, path)
        return yaml.safe_load(text)
    except yaml.constructor.ConstructorError as e:
        raise Unresolved(f'{path}: YAML uses a tag that is not read '
                         f'statically ({_first_line(e)})')
    except yaml.YAMLError as e:
        raise LaunchError(f'{path}: malformed YAML ({_first_line(e)}).')
    except (RecursionError, MemoryError):
        raise LaunchError(f'{path}: the YAML is nested too deeply.')


# libyaml's parser when PyYAML has it: counting is then some seconds
_EVENT_LOADER = getattr(yaml, 'CSafeLoader', yaml.SafeLoader)
_NODE_EVENTS = (yaml.ScalarEvent, yaml.AliasEvent, yaml.MappingStartEvent,
                yaml.SequenceStartEvent)


def _count_values(text, path):
    """Raise LaunchError as soon as the text holds too many values.

    A value is what :func:`check_value` counts: a scalar, a list or a
    mapping, not a mapping's key. Malformed YAML is left to the loader,
    which says what is wrong.
    """
    try:
        _count_events(yaml.parse(text, Loader=_EVENT_LOADER), path)
    except yaml.YAMLError:
        pass


def _count_events(events, path):
    values = 0
    # for each open mapping or list: whether its next node is a key
    keys = []
    for event in events:
        if isinstance(event, _NODE_EVENTS):
            is_key = bool(keys) and keys[-1]
            if keys and keys[-1] is not None:
                keys[-1] = not keys[-1]
            if not is_key:
                values += 1
                if values > MAX_YAML_VALUES:
                    raise LaunchError(
                        f'{path}: holds more than {MAX_YAML_VALUES:,} values '
                        '(a parameter file holds some thousands); not read.')
            if isinstance(event, yaml.MappingStartEvent):
                keys.append(True)
            elif isinstance(event, yaml.SequenceStartEvent):
                keys.append(None)
        elif isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
            keys.pop()


def _first_line(error):
    text = str(error).strip().splitlines()
    return ' '.join(t.strip() for t in text[:3]) if text else 'error'


def check_value(value, path, budget=None):
    """Check that a YAML value is finite and small enough to keep.

    :raises LaunchError: for recursive values or alias bombs
    """
    budget = budget if budget is not None else [MAX_PARAMETERS * 10]
    _check_value(value, path, budget, 0, set())
    return value


def _check_value(value, path, budget, depth, active):
    budget[0] -= 1
    if budget[0] < 0:
        raise LaunchError(f'{path}: the YAML expands to too many values '
                          '(nested aliases?).')
    if depth > MAX_NESTING:
        raise LaunchError(f'{path}: the YAML is nested too deeply or '
                          'refers to itself.')
    if isinstance(value, (dict, list)):
        if id(value) in active:
            raise LaunchError(f'{path}: the YAML refers to itself.')
        active.add(id(value))
        items = value.values() if isinstance(value, dict) else value
        for item in items:
            _check_value(item, path, budget, depth + 1, active)
        active.discard(id(value))


def flatten(value, prefix, separator, out, path):
    """Flatten nested dicts into ``a<sep>b`` keys of ``out`` (in order)."""
    check_value(value, path)
    _flatten(value, prefix, separator, out)
    return out


def _flatten(value, prefix, separator, out):
    if isinstance(value, dict) and value:
        for key, item in value.items():
            name = f'{prefix}{separator}{key}' if prefix else str(key)
            _flatten(item, name, separator, out)
    elif prefix:
        out[prefix] = value


def typed_value(text):
    """A ROS 2 parameter value from its text (YAML typing, else the text)."""
    if not isinstance(text, str):
        return text
    try:
        value = yaml.safe_load(text)
    except (yaml.YAMLError, RecursionError, MemoryError):
        return text
    if isinstance(value, dict) or value is None and text.strip() not in (
            '~', 'null', 'Null', 'NULL'):
        return text
    if isinstance(value, list):
        try:
            check_value(value, 'value')
        except LaunchError:
            return text
        if any(isinstance(v, (dict, list)) for v in value):
            return text
    return value


# ROS names


def join_ns(base, ns):
    """A namespace inside another (an absolute one replaces it)."""
    if ns is None:
        return base
    if base is None and not str(ns).startswith('/'):
        return None
    text = str(ns)
    if text.startswith('/'):
        return normalise_ns(text)
    return normalise_ns(f'{base}/{text}')


def normalise_ns(ns):
    """'/a/b' form of a namespace; '/' for the root."""
    if ns is None:
        return None
    parts = [p for p in str(ns).split('/') if p]
    return '/' + '/'.join(parts)


def fqn(namespace, name):
    """The fully qualified node name, None when a part is not known."""
    if namespace is None or name is None:
        return None
    return normalise_ns(f'{namespace}/{name}')


# ROS 2 parameter files


def ros2_param_sections(data, path):
    """``(node name pattern, parameters)`` of a ROS 2 parameter file.

    :raises Unresolved: when the file is not a mapping of node names
    """
    if data is None:
        return []
    if not isinstance(data, dict):
        raise Unresolved(f'{path}: not a ROS 2 parameter file (it must map '
                         'node names to ros__parameters)')
    check_value(data, path)
    sections = []
    _sections(data, '', sections, 0)
    return sections


def _sections(data, prefix, sections, depth):
    if depth > MAX_NESTING:
        return
    for key, value in data.items():
        if key == 'ros__parameters':
            if isinstance(value, dict):
                sections.append((normalise_ns(prefix), value))
            continue
        if isinstance(value, dict):
            _sections(value, f'{prefix}/{key}', sections, depth + 1)


def pattern_matches(pattern, node_fqn):
    """Whether a parameter file node pattern (with * and **) matches."""
    regex = _pattern_regex(pattern)
    return regex.fullmatch(node_fqn) is not None


def _pattern_regex(pattern):
    parts = []
    for part in pattern.split('/'):
        if part and not (part == '**' and parts and parts[-1] == '**'):
            parts.append(part)
    pattern = '/' + '/'.join(parts)
    if len(pattern) > MAX_PATTERN_LENGTH or pattern.count('*') > \
            MAX_PATTERN_WILDCARDS:
        return re.compile(r'(?!)')  # matches nothing
    out = []
    i = 0
    while i < len(pattern):
        if pattern.startswith('/**', i):
            out.append('(/[^/]+)*')
            i += 3
        elif pattern[i] == '*':
            out.append('[^/]*')
            i += 1
        else:
            out.append(re.escape(pattern[i]))
            i += 1
    return re.compile(''.join(out))


def is_wildcard_for_all(pattern):
    """Whether a pattern matches every node whatever its name (``/**``)."""
    parts = [p for p in pattern.split('/') if p]
    return bool(parts) and all(p == '**' for p in parts)


def params_from_sections(sections, node_fqn, out, path, notes,
                         namespace=None):
    """Add the parameters of the sections that apply to a node to ``out``.

    :param node_fqn: the node's fully qualified name, None when not known
    """
    skipped = []
    for pattern, values in sections:
        if node_fqn is not None:
            applies = pattern_matches(pattern, node_fqn)
        elif is_wildcard_for_all(pattern):
            applies = True
        else:
            applies = False
            skipped.append(pattern)
        if applies:
            flatten(values, '', '.', out, path)
    if skipped:
        notes.append(
            f'{path}: parameter sections {", ".join(skipped)} not applied: '
            'the node name is not known statically')


def parse_bool(text, what):
    """A launch condition's truth value ('true'/'false'/'1'/'0')."""
    value = str(text).strip().lower()
    if value in ('true', '1'):
        return True
    if value in ('false', '0'):
        return False
    raise Unresolved(f"{what}: '{shorten(text)}' is not true or false")


def resolve_path(path, current_file):
    """A file path relative to the directory of the current file."""
    if os.path.isabs(path):
        return os.path.normpath(path)
    return os.path.normpath(
        os.path.join(os.path.dirname(os.path.abspath(current_file)), path))


def ros_arguments(tokens, remaps, params, notes, where, *, after_ros_args):
    """Read ``--ros-args -r a:=b -p x:=1`` style node arguments.

    :param list tokens: the arguments (strings)
    :param bool after_ros_args: the tokens are ROS arguments already
      (``ros_arguments=``); else only those after ``--ros-args`` count
    :returns: dict of '__node'/'__ns' overrides found
    """
    overrides = {}
    active = after_ros_args
    i = 0
    while i < len(tokens):
        token = tokens[i]
        if token == '--ros-args':
            active = True
        elif token == '--':
            active = after_ros_args
        elif active and token in ('-r', '--remap', '-p', '--param',
                                  '--params-file') and i + 1 < len(tokens):
            value = tokens[i + 1]
            i += 1
            if token in ('-r', '--remap'):
                _ros2_remap(value, remaps, overrides)
            elif token in ('-p', '--param'):
                name, sep, text = value.partition(':=')
                if sep:
                    params[name] = typed_value(text)
            else:
                notes.append(f'{where}: parameter file {value} given as a '
                             'node argument is not read')
        i += 1
    return overrides


def _ros2_remap(text, remaps, overrides):
    source, sep, target = text.partition(':=')
    if not sep:
        return
    if ':' in source and not source.startswith(('/', '~')):
        source = source.split(':', 1)[1]  # node-specific 'node:from:=to'
    if source in ('__node', '__name', '__ns'):
        overrides[source] = target
    else:
        remaps.append((source, target))


# substitutions only ROS 1 launch files use
_ROS1_SUBSTITUTIONS = ('$(find ', '$(arg ', '$(optenv ')
# elements only ROS 2 XML launch files use
_ROS2_ELEMENTS = frozenset((
    'let', 'push-ros-namespace', 'push_ros_namespace', 'node_container',
    'set_remap', 'set_parameter', 'load_composable_node'))


def file_kind(path, text, root=None):
    """Which front end reads a launch file.

    :param root: the parsed XML (an ``Elem``), when already parsed
    :returns: 'python', 'yaml', 'ros1' (ROS 1 XML) or 'ros2' (ROS 2 XML)
    """
    name = os.path.basename(str(path)).lower()
    if name.endswith('.py'):
        return 'python'
    if name.endswith(('.yaml', '.yml')):
        return 'yaml'
    if root is None:
        try:
            root = parse_xml(text, path)
        except LaunchError:
            root = None
    ros1, ros2 = _xml_markers(root) if root is not None else (False, False)
    if ros1:
        return 'ros1'
    if ros2:
        return 'ros2'
    return 'ros1' if name.endswith('.launch') else 'ros2'


def _xml_markers(root):
    """Whether ROS 1 only and ROS 2 only constructs are used."""
    ros1 = ros2 = False
    stack = [root]
    while stack:
        elem = stack.pop()
        if elem.tag == 'node':
            ros1 = ros1 or 'type' in elem.attrs
            ros2 = ros2 or 'exec' in elem.attrs
        ros1 = ros1 or elem.tag == 'rosparam'
        ros2 = ros2 or elem.tag in _ROS2_ELEMENTS
        for value in elem.attrs.values():
            if '$(' in value:
                ros1 = ros1 or any(m in value for m in _ROS1_SUBSTITUTIONS)
                ros2 = ros2 or '$(var ' in value or '$(find-pkg-' in value
        if ros1:
            break
        stack.extend(elem.children)
    return ros1, ros2
