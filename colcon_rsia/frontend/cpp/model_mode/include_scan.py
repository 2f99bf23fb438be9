# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The includes of a unit, followed through the files we can read.

Which includes the model headers or the workspace's sources provide, and
which are missing (and get a stand-in); whether the unit is ROS 2 code.
"""

import glob
import os
import re

from colcon_rsia import safe_files
from colcon_rsia.frontend.cpp.model_mode.arguments import is_inside
from colcon_rsia.frontend.cpp.model_mode.arguments import real_path
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR

# include prefixes of C/POSIX/Linux system headers: left to the compiler
SYSTEM_PREFIXES = (
    'sys/', 'bits/', 'linux/', 'arpa/', 'netinet/', 'asm/', 'asm-generic/',
    'net/', 'netpacket/', 'scsi/', 'rpc/', 'ext/', 'tr1/', 'experimental/',
    'gnu/', 'c++/',
)


INCLUDE = re.compile(
    r'^[ \t]*#[ \t]*(?:include|include_next|import)[ \t]*([<"])([^>"\n]+)[>"]',
    re.MULTILINE)


# the model headers the model mode writes into the stub directory (stubs.py)
GENERATED_PREFIX = 'rsia_model/'
# includes only ROS 2 code has: rclcpp, generated ROS 2 interfaces, and
# the `.hpp` headers of libraries whose ROS 1 versions have `.h` ones
_ROS2_INCLUDE = re.compile(
    r'^(?:rclcpp(?:_\w+)?/'
    r'|\w+/(?:msg|srv|action)/\w+\.hpp$'
    r'|(?:image_transport|message_filters|realtime_tools|diagnostic_updater'
    r'|tf2_ros)/.*\.hpp$)')


_model_includes_cache = {}
_system_dirs_cache = []


class FileCache:
    """Whether paths are files or directories, asked once.

    The units of one package search the same include directories for the
    same headers (hundreds of directories in a large workspace): one cache
    serves them all. Only for the time of one package's preparation: the
    stand-ins written meanwhile are outside the directories searched.
    """

    def __init__(self):  # noqa: D107
        self._isfile = {}
        self._isdir = {}
        self._real = {}
        # {(search directories, include name): the file it finds}
        self.found = {}

    def realpath(self, path):  # noqa: D102
        found = self._real.get(path)
        if found is None:
            found = self._real[path] = real_path(path)
        return found

    def isfile(self, path):  # noqa: D102
        found = self._isfile.get(path)
        if found is None:
            found = self._isfile[path] = os.path.isfile(path)
        return found

    def isdir(self, path):  # noqa: D102
        found = self._isdir.get(path)
        if found is None:
            found = self._isdir[path] = os.path.isdir(path)
        return found


class Scanner:
    """Follows the includes of a source through the files we can read."""

    def __init__(self, *, roots, search, stub_dir,  # noqa: D107
                 before_model=(), files=None):
        self.roots = roots
        self.search = search
        self.stub_dir = stub_dir
        self.quote_dirs = [d for kind, d in search if kind == '-iquote']
        # in the order the parse searches them (see prepare_model_arguments)
        self.angle_dirs = list(before_model) + [MODEL_HEADERS_DIR] + [
            d for kind, d in search
            if kind != '-iquote' and d not in before_model]
        self.visited = set()
        # include name -> 'stub' (a stand-in by its name) | 'empty' (a
        # system header this machine lacks)
        self.missing = {}
        # the missing includes a model header makes (its messages)
        self.included_by_model = set()
        self.user_texts = []
        self.files = files or FileCache()
        # the directories an include searches after its own (keys of
        # files.found)
        self._angle_dirs = tuple(self.angle_dirs)
        self._quote_dirs = tuple(self.quote_dirs) + self._angle_dirs
        # whether the package's own code includes a ROS 2 header (the dual
        # model headers include ROS 2 ones behind #ifdef: theirs never count)
        self.ros2 = False

    def scan(self, source):
        """Follow the includes of `source`, and of the headers it reaches."""
        todo = [source]
        while todo:
            path = todo.pop()
            if path in self.visited:
                continue
            self.visited.add(path)
            user_file = not path.startswith(MODEL_HEADERS_DIR + os.sep)
            for quoted, name in self._includes(path):
                found = self.resolve(name, quoted, os.path.dirname(path))
                if user_file and _ROS2_INCLUDE.match(name):
                    self.ros2 = True
                if found is not None:
                    if found not in self.visited and self._scannable(found):
                        todo.append(found)
                    continue
                if self._is_system(name):
                    if not self._in_system_dirs(name):
                        self.missing[name] = 'empty'
                    continue
                if name.startswith(GENERATED_PREFIX):
                    continue  # merged into the stub directory, never stood in
                self.missing.setdefault(name, 'stub')
                if not user_file:
                    self.included_by_model.add(name)

    def _includes(self, path):
        if path.startswith(MODEL_HEADERS_DIR + os.sep):
            cached = _model_includes_cache.get(path)
            if cached is None:
                cached = _read_includes(read_text(path) or '')
                _model_includes_cache[path] = cached
            return cached
        text = read_text(path)
        if text is None:
            return []
        self.user_texts.append(text)
        return _read_includes(text)

    def _scannable(self, path):
        if path.startswith(MODEL_HEADERS_DIR + os.sep):
            return True
        real = self.files.realpath(path)
        return any(is_inside(real, root) for root in self.roots)

    def resolve(self, name, quoted, including_dir):
        """The file an include finds in the model or source directories."""
        if os.path.isabs(name):
            return name if self._exists(name) else None
        if quoted:
            found = self._first(name, [including_dir])
            if found is not None:
                return found
            key = (self._quote_dirs, name)
        else:
            key = (self._angle_dirs, name)
        if key not in self.files.found:
            self.files.found[key] = self._first(name, key[0])
        return self.files.found[key]

    def _first(self, name, dirs):
        for directory in dirs:
            candidate = os.path.normpath(os.path.join(directory, name))
            if self._exists(candidate):
                return candidate
        return None

    def _exists(self, path):
        return self.files.isfile(path)

    @staticmethod
    def _is_system(name):
        return '/' not in name or name.startswith(SYSTEM_PREFIXES)

    def _in_system_dirs(self, name):
        return any(self._exists(os.path.join(d, name))
                   for d in _system_include_dirs())


def read_text(path):
    """A file's text, or None when it cannot be read safely."""
    try:
        # checked: a header may be a link to /dev/zero, or a FIFO
        data = safe_files.read_bytes(path)
    except OSError:
        return None
    return data.decode('utf-8', errors='surrogateescape')


def write_atomically(path, content):
    """Write a text file whole or not at all (readers never see half).

    Stand-ins keep undecodable names as they were read.
    """
    safe_files.write_text_atomically(path, content, errors='surrogateescape')


def _read_includes(text):
    return [(m.group(1) == '"', m.group(2).strip())
            for m in INCLUDE.finditer(text)]


def _system_include_dirs():
    """The compiler's own include directories (standard, POSIX, Linux)."""
    if not _system_dirs_cache:
        from colcon_rsia.frontend.compile_db import find_resource_dir
        dirs = []
        resource_dir = find_resource_dir()
        if resource_dir:
            dirs.append(os.path.join(resource_dir, 'include'))
        for pattern in ('/usr/include/c++/*', '/usr/include/*/c++/*',
                        '/usr/include/c++/*/backward'):
            dirs += sorted(glob.glob(pattern), reverse=True)
        dirs += ['/usr/local/include']
        dirs += sorted(glob.glob('/usr/include/*-linux-gnu*'))
        dirs += ['/usr/include']
        _system_dirs_cache.append([d for d in dirs if os.path.isdir(d)])
    return _system_dirs_cache[0]
