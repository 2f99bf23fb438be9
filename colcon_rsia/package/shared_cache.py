# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The shared fact cache: ``$COLCON_RSIA_CACHE_DIR``, keyed by content.

The per-package cache (``cache.py``) is keyed by where a unit is and the
modification times of what it read: right for one checkout, useless to a
second clone, a CI job on another machine or a colleague's workspace. This
cache is keyed only by what decides a unit's facts: the tool and its facts
schema, the front end's code, the compiler arguments with the checkout's
own directories replaced by placeholders, the wrapper summaries the unit
was walked with, and the content of the unit and of every file it
included. Several runs, checkouts and machines may share the directory.

An entry is ``<dir>/v1/<kk>/<base>-<inputs>.json``: ``base`` the digest of
everything known before the parse (the source's content among it),
``inputs`` that of the files the parse included, each named relative to
the package, its build directory, colcon-rsia's own directory or the
workspace, or (system headers) by its absolute path, with the sha256 of its
content. A lookup reads the entries of the unit's ``base`` and takes the
first whose inputs all still hash the same. Facts and input names hold
placeholders instead of the checkout's directories, put back on load.

Entries are written whole (a temporary file named with the pid, renamed),
so concurrent writers need no lock; one that cannot be read or is not
ours is removed and written again by the next parse. The directory is kept
under ``COLCON_RSIA_CACHE_MB`` by removing the least recently used entries
(a hit touches its entry).
"""

import hashlib
import json
import os
import re
import threading
import time

from colcon_rsia import __version__
from colcon_rsia import safe_files
from colcon_rsia.environment_variables import CACHE_DIR_ENVIRONMENT_VARIABLE
from colcon_rsia.environment_variables import CACHE_MB_ENVIRONMENT_VARIABLE
from colcon_rsia.frontend.facts import FACTS_SCHEMA
from colcon_rsia.frontend.facts import TuFacts
from colcon_rsia.package.cache import _frontend_digest
from colcon_rsia.package.settings import positive_number

DEFAULT_CACHE_MB = 1024
# a new layout (or a new meaning of an entry) gets a new directory: old
# entries are then only evicted, never misread
LAYOUT = 'v1'
ENTRY_SCHEMA = 'colcon-rsia/shared-facts@1'
# the facts of one unit are a few KB to a few MB; a larger file is not one
# of ours
MAX_ENTRY_BYTES = 64 << 20
# the digest of an include that is not a file we can read: libclang named
# a header of the precompiled standard headers by a path that is not where
# it is now (the PCH's name holds what it was made from); the package's
# cache takes such a file as unchanged while it stays missing, and so does
# this one
ABSENT = 'absent'
# a temporary file older than this was left by a writer that was killed
STALE_TEMPORARY_S = 3600
# eviction goes below the limit by this much, so that the next runs do not
# each scan the directory to remove one entry
EVICT_TO = 0.9
# the placeholders of the checkout's directories, as they are written in
# keys and entries (most specific first when a file is named)
PACKAGE, BUILD, TOOL, WORKSPACE = (
    '<<rsia:package>>', '<<rsia:build>>', '<<rsia:tool>>',
    '<<rsia:workspace>>')
UNIT = '<<rsia:unit>>'
_PLACEHOLDER_MARK = '<<rsia:'
# colcon_rsia's own directory: the model headers are in it; this module is
# in colcon_rsia/package
_TOOL_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# what the lookups of this process found, for the line `analyze` prints
_stats_lock = threading.Lock()
_stats = {'hits': 0, 'lookups': 0, 'result_hits': 0, 'results': 0}


def statistics():
    """(units found, units looked up) in the shared cache by this process."""
    with _stats_lock:
        return _stats['hits'], _stats['lookups']


def statistics_line():
    """What the shared cache gave this process, or None when it is not set.

    Printed at the end of an analysis: what a CI cache is kept for.
    """
    directory = cache_directory()
    if directory is None:
        return None
    hits, lookups = statistics()
    return safe_files.printable(
        f'rsia: shared cache: {hits} of {lookups} translation units found '
        f'in {directory}')


def _count_result(hit):
    with _stats_lock:
        _stats['results'] += 1
        _stats['result_hits'] += bool(hit)


def _count(hit):
    with _stats_lock:
        _stats['lookups'] += 1
        _stats['hits'] += bool(hit)


# --- the variables -----------------------------------------------------------

def cache_directory():
    """The shared cache's directory (absolute), or None when not set."""
    value = os.environ.get(CACHE_DIR_ENVIRONMENT_VARIABLE.name, '').strip()
    return os.path.abspath(value) if value else None


def cache_bytes():
    """The size the directory is kept under (``COLCON_RSIA_CACHE_MB``).

    :raises ValueError: one sentence, when the value is not a positive
      number of megabytes
    """
    return int(positive_number(
        CACHE_MB_ENVIRONMENT_VARIABLE.name, default=DEFAULT_CACHE_MB,
        unit='megabytes', what='the size of the shared fact cache') *
        (1 << 20))


def settings_problems():
    """One sentence for each bad value of the shared cache's variables."""
    problems = []
    try:
        cache_bytes()
    except ValueError as e:
        problems.append(str(e))
    directory = cache_directory()
    if directory is None:
        return problems
    name = CACHE_DIR_ENVIRONMENT_VARIABLE.name
    raw = os.environ[name]
    if os.path.exists(directory):
        if not os.path.isdir(directory):
            problems.append(f'{name}={raw!r} is not a directory')
        elif not os.access(directory, os.R_OK | os.X_OK):
            problems.append(f'{name}={raw!r} is a directory we cannot read')
        return problems
    # made at the first write: the nearest directory that exists must let
    # us make it
    parent = os.path.dirname(directory)
    while not os.path.exists(parent):
        parent = os.path.dirname(parent)
    if not os.path.isdir(parent) or not os.access(parent, os.W_OK | os.X_OK):
        problems.append(
            f'{name}={raw!r} does not exist and cannot be made ({parent} '
            'is not a directory we can write)')
    return problems


# --- naming without the checkout's directories -------------------------------

def _pattern(root):
    # the root as a whole path: at the start of the text or after what
    # starts a path in a message or an argument, and followed by its end or
    # a separator (so that /ws/pkg is not found in /ws/pkg2 or /x/ws/pkg)
    return re.compile(r'(?<![^\s"\'@=:(,\[])' + re.escape(root) +
                      r'(?![^/\s"\':;,)\]>])')


class SharedCache:
    """The shared cache as one package's analysis uses it (picklable).

    :param directory: ``COLCON_RSIA_CACHE_DIR``
    :param roots: [(placeholder, absolute directory)] of the checkout
    :param salt: more of what decides the facts, with placeholders (the
      clang resource directory, the files libclang is given as empty)
    """

    def __init__(self, directory, limit, roots, salt=''):  # noqa: D107
        self.directory = directory
        self.limit = limit
        # the longest first: a package is inside its workspace
        self.roots = sorted(
            ((p, r.rstrip('/') or '/') for p, r in roots if r),
            key=lambda pr: -len(pr[1]))
        self.salt = salt

    @classmethod
    def from_environment(cls, *, package_path, build_base,
                         workspace_package_dirs=(), resource_dir=None):
        """The shared cache of a package, or None when it is not set."""
        directory = cache_directory()
        if directory is None:
            return None
        package_path = os.path.abspath(package_path)
        build_base = os.path.abspath(build_base)
        # the workspace: what holds the packages and the build directories
        # (a second clone has the same layout under another root); none
        # when only / holds them
        workspace = os.path.commonpath(
            [package_path, os.path.dirname(build_base)] +
            [os.path.abspath(d) for d in workspace_package_dirs])
        roots = [(PACKAGE, package_path), (BUILD, build_base),
                 (TOOL, _TOOL_DIR)]
        if workspace != os.sep:
            roots.append((WORKSPACE, workspace))
        shared = cls(directory, cache_bytes(), roots)
        shared.salt = shared.to_placeholders(resource_dir or '')
        return shared

    @classmethod
    def of_package(cls, package_path, build_base):
        """The shared cache of what is read of a package as a whole.

        Its results name the package's files and its build directory only;
        None when the variable is not set.
        """
        directory = cache_directory()
        if directory is None:
            return None
        return cls(directory, cache_bytes(), [
            (PACKAGE, os.path.abspath(package_path)),
            (BUILD, os.path.abspath(build_base))])

    def with_hidden(self, hidden):
        """This cache for units that see the files of ``hidden`` empty."""
        salt = json.dumps([self.salt, sorted(
            [self.to_placeholders(f), self.to_placeholders(why)]
            for f, why in hidden.items())])
        return SharedCache(self.directory, self.limit, self.roots, salt)

    def to_placeholders(self, text):
        """``text`` with the checkout's directories as placeholders."""
        for placeholder, root in self.roots:
            text = _pattern(root).sub(placeholder, text)
        return text

    def _from_placeholders_json(self, text):
        # the directories as json.dumps writes them in a string
        for placeholder, root in self.roots:
            text = text.replace(placeholder, json.dumps(root)[1:-1])
        return text

    def _argument(self, argument):
        # -I/ws/include, --sysroot=/x: the path after the flag
        match = re.match(r'(-[\w+-]*=?)(/.*)', argument, re.S)
        if match:
            return match.group(1) + self.to_placeholders(match.group(2))
        return self.to_placeholders(argument)

    def _name(self, path):
        """A file's name without the checkout: placeholder + relative."""
        path = os.path.abspath(path)
        for placeholder, root in self.roots:
            if safe_files.is_inside(path, root):
                return placeholder + '/' + os.path.relpath(path, root)
        return path

    def _base_key(self, entry, wrappers_digest):
        """The digest of what decides the facts, known before parsing."""
        source = _content_digest(entry.file)
        if source is None:
            return None
        # the model mode's repair header is named by a digest of the unit's
        # absolute path (recovery/store.py): the same file in every clone
        path_digest = hashlib.sha1(os.path.abspath(entry.file).encode(
            'utf-8', 'surrogateescape')).hexdigest()[:16]
        key = {'tool': __version__, 'schema': FACTS_SCHEMA,
               'frontend': _frontend_digest(),
               'file': self._name(entry.file),
               'directory': self._name(entry.directory),
               'arguments': [self._argument(a).replace(path_digest, UNIT)
                             for a in entry.arguments],
               'wrappers': wrappers_digest, 'salt': self.salt,
               'source': source}
        return hashlib.sha256(json.dumps(
            key, sort_keys=True).encode('utf-8', 'surrogateescape')
        ).hexdigest()[:40]

    def _shard(self, base):
        return os.path.join(self.directory, LAYOUT, base[:2])

    # --- lookup --------------------------------------------------------------

    def lookup(self, entry, wrappers_digest):
        """(facts, the files they were read from) of a unit, or None."""
        found = self._lookup(entry, wrappers_digest)
        _count(found is not None)
        return found

    def _lookup(self, entry, wrappers_digest):
        base = self._base_key(entry, wrappers_digest)
        if base is None:
            return None
        shard = self._shard(base)
        try:
            with os.scandir(shard) as scan:
                candidates = [(e.stat().st_mtime, e.path) for e in scan
                              if e.name.startswith(base + '-') and
                              e.name.endswith('.json')]
        except OSError:
            return None
        # the most recently used first: the likeliest to match
        for _, path in sorted(candidates, reverse=True):
            data = self._read(path)
            if data is None:
                continue
            if all((_content_digest(name) or ABSENT) == digest
                   for name, digest in data['inputs']):
                try:
                    os.utime(path)  # used now: evicted last
                except OSError:
                    pass  # a cache we may only read
                return data['facts'], [entry.file] + [
                    name for name, _ in data['inputs']]
        return None

    def _read(self, path):
        """An entry with this checkout's directories, or None when bad.

        A bad entry (truncated, corrupted, not ours) is removed: the next
        parse of its unit writes it again.
        """
        try:
            with open(path, 'rb') as h:
                raw = h.read(MAX_ENTRY_BYTES + 1)
        except OSError:
            return None  # evicted meanwhile
        try:
            if len(raw) > MAX_ENTRY_BYTES:
                raise ValueError('too large')
            data = json.loads(self._from_placeholders_json(
                raw.decode('utf-8')))
            if data['schema'] != ENTRY_SCHEMA:
                raise ValueError('not ours')
            inputs = [(name, digest) for name, digest in data['inputs']
                      if isinstance(name, str) and isinstance(digest, str)]
            if len(inputs) != len(data['inputs']):
                raise ValueError('not ours')
            return {'inputs': inputs,
                    'facts': TuFacts.from_dict(data['facts'])}
        except (ValueError, KeyError, TypeError, AttributeError,
                UnicodeDecodeError):
            _remove(path)
            return None

    # --- store ---------------------------------------------------------------

    def store(self, entry, wrappers_digest, includes, facts):
        """Keep a unit's facts, parsed with the files of ``includes``."""
        base = self._base_key(entry, wrappers_digest)
        if base is None:
            return
        named = [[self._name(path), _content_digest(path) or ABSENT]
                 for path in includes]
        facts = facts.to_dict()
        if _PLACEHOLDER_MARK in json.dumps(facts):
            return  # the code itself holds our marks: not reversible
        digest = hashlib.sha256(json.dumps(
            named, sort_keys=True).encode('utf-8', 'surrogateescape')
        ).hexdigest()[:24]
        path = os.path.join(self._shard(base), f'{base}-{digest}.json')
        # the facts name the package's files relative to it; what else
        # they say of the checkout's directories (a message quoting a
        # header of another package) is written with placeholders too
        text = self._to_placeholders_json(json.dumps(
            {'schema': ENTRY_SCHEMA, 'inputs': named, 'facts': facts},
            sort_keys=True))
        try:
            safe_files.write_text_atomically(path, text)
        except OSError:
            pass  # a cache that cannot be written only costs time

    def _to_placeholders_json(self, text):
        for placeholder, root in self.roots:
            text = _pattern(json.dumps(root)[1:-1]).sub(placeholder, text)
        return text

    # --- results other than a unit's facts ----------------------------------

    def _result_path(self, kind, key):
        return os.path.join(self._shard(key), f'{kind}-{key}.json')

    def lookup_result(self, kind, key):
        """The JSON data kept with :meth:`store_result`, or None.

        :param kind: what it is (a word: the entry's name starts with it)
        :param key: a digest of everything that decides the data, in
          which no directory of the checkout may be
        """
        path = self._result_path(kind, key)
        try:
            with open(path, 'rb') as h:
                raw = h.read(MAX_ENTRY_BYTES + 1)
        except OSError:
            _count_result(False)
            return None
        try:
            if len(raw) > MAX_ENTRY_BYTES:
                raise ValueError('too large')
            data = json.loads(self._from_placeholders_json(
                raw.decode('utf-8')))
            if data['schema'] != ENTRY_SCHEMA or data['kind'] != kind:
                raise ValueError('not ours')
        except (ValueError, KeyError, TypeError, UnicodeDecodeError):
            _remove(path)
            _count_result(False)
            return None
        try:
            os.utime(path)
        except OSError:
            pass
        _count_result(True)
        return data['data']

    def store_result(self, kind, key, data):
        """Keep JSON data under ``key`` (see :meth:`lookup_result`)."""
        if _PLACEHOLDER_MARK in json.dumps(data):
            return
        text = self._to_placeholders_json(json.dumps(
            {'schema': ENTRY_SCHEMA, 'kind': kind, 'data': data},
            sort_keys=True))
        try:
            safe_files.write_text_atomically(
                self._result_path(kind, key), text)
        except OSError:
            pass

    # --- size ------------------------------------------------------------------

    def evict(self):
        """Remove the least recently used entries beyond the size limit."""
        top = os.path.join(self.directory, LAYOUT)
        lock = _try_lock(self.directory)
        if lock is False:
            return  # another process is evicting now
        try:
            entries, total = [], 0
            now = time.time()
            try:
                shards = [e.path for e in os.scandir(top) if e.is_dir()]
            except OSError:
                return
            for shard in shards:
                try:
                    with os.scandir(shard) as scan:
                        for e in scan:
                            st = e.stat()
                            if e.name.startswith('.'):
                                if now - st.st_mtime > STALE_TEMPORARY_S:
                                    _remove(e.path)
                                continue
                            entries.append((st.st_mtime, e.path, st.st_size))
                            total += st.st_size
                except OSError:
                    continue
            if total <= self.limit:
                return
            for _, path, size in sorted(entries):
                if total <= self.limit * EVICT_TO:
                    break
                _remove(path)
                total -= size
        finally:
            if lock is not None:
                os.close(lock)


def _try_lock(directory):
    """Take the directory's lock if it is free.

    :returns: the descriptor holding it; None where there are no locks;
      False when another process holds it
    """
    try:
        import fcntl
        fd = os.open(directory, os.O_RDONLY | os.O_CLOEXEC)
    except (ImportError, OSError):
        return None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        return False
    return fd


def _remove(path):
    try:
        os.unlink(path)
    except OSError:
        pass


# the digests of the files this process hashed, by path: a header every
# unit includes is read once; trusted while its stat is the same
_digests = {}
_digests_lock = threading.Lock()


def _content_digest(path):
    """The sha256 of a file's content, or None when it cannot be read."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    stamp = (st.st_ino, st.st_size, st.st_mtime_ns, st.st_ctime_ns)
    with _digests_lock:
        known = _digests.get(path)
    if known is not None and known[0] == stamp:
        return known[1]
    digest = hashlib.sha256()
    try:
        with open(path, 'rb') as h:
            for block in iter(lambda: h.read(1 << 20), b''):
                digest.update(block)
    except OSError:
        return None
    with _digests_lock:
        _digests[path] = (stamp, digest.hexdigest())
    return digest.hexdigest()
