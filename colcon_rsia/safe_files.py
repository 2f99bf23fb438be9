# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Read the files of an analysed workspace without trusting them.

A pull request can make any file of a package a symlink to ``/dev/zero``
or ``/proc/self/environ``, a FIFO, or 50 MB of generated code. Every file
the analysis reads from a package goes through :func:`read_bytes`: it
must be a regular file whose real path stays inside the package (or an
explicitly allowed directory), no larger than the size limit; it is
opened without blocking and checked again on the open descriptor, so a
file swapped after the check is caught too.
"""

import contextlib
import json
import math
import os
import re
import stat
import tempfile

from colcon_rsia.environment_variables import \
    ALLOWED_ROOTS_ENVIRONMENT_VARIABLE
from colcon_rsia.environment_variables import \
    MAX_FILE_MB_ENVIRONMENT_VARIABLE

# a hand-written source file is rarely above 1 MB; generated ones reach a
# few MB; a 50 MB module costs gigabytes of memory and minutes to parse
DEFAULT_MAX_FILE_MB = 8


class UnsafeFileError(OSError):
    """A file the analysis does not read; ``str()`` says why and what to do.

    An :class:`OSError`, so that every reader's existing handling of an
    unreadable file applies to it.
    """

    def __init__(self, message):  # noqa: D107
        super().__init__(message)
        self.strerror = message

    def __str__(self):  # noqa: D105
        return self.strerror


def _max_file_mb():
    """The size limit in MB, or None when the variable holds no limit."""
    value = os.environ.get(MAX_FILE_MB_ENVIRONMENT_VARIABLE.name)
    if not value:
        return DEFAULT_MAX_FILE_MB
    try:
        megabytes = float(value)
    except ValueError:
        return None
    return megabytes if math.isfinite(megabytes) and megabytes > 0 \
        else None


def max_file_mb_problem():
    """What is wrong with the size limit's variable, or None.

    Checked up front by every command (see
    :mod:`colcon_rsia.package.environment`).
    """
    if _max_file_mb() is not None:
        return None
    return (f'{MAX_FILE_MB_ENVIRONMENT_VARIABLE.name}='
            f"'{os.environ[MAX_FILE_MB_ENVIRONMENT_VARIABLE.name]}': "
            'expected a number of megabytes above 0')


def max_file_bytes():
    """The size limit of a file read from a package, in bytes."""
    # a bad value was reported up front: the default, never a traceback
    return int((_max_file_mb() or DEFAULT_MAX_FILE_MB) * 1024 * 1024)


def allowed_roots(roots):
    """The real paths of ``roots`` and of the explicitly allowed ones."""
    extra = os.environ.get(ALLOWED_ROOTS_ENVIRONMENT_VARIABLE.name, '')
    return [os.path.realpath(r) for r in
            list(roots) + [e for e in extra.split(os.pathsep) if e]]


def is_inside(path, directory):
    """Whether ``path`` is ``directory`` or below it (no resolving)."""
    directory = directory.rstrip(os.sep) or os.sep
    return path == directory or path.startswith(
        directory if directory == os.sep else directory + os.sep)


def _check_root(path, roots):
    if roots is None:
        return
    real = os.path.realpath(path)
    if not any(is_inside(real, r) for r in allowed_roots(roots)):
        raise UnsafeFileError(
            f"is a link to '{display(real)}', outside the package; not "
            f'read (add the directory to {ALLOWED_ROOTS_ENVIRONMENT_VARIABLE.name} '
            'to allow it)')


def _check_stat(st, limit):
    if not stat.S_ISREG(st.st_mode):
        raise UnsafeFileError(
            f'is not a regular file ({_kind(st.st_mode)}); not read')
    if st.st_size > limit:
        raise UnsafeFileError(_too_large(st.st_size, limit))


def _too_large(size, limit):
    return (
        f'is larger than the size limit ({size / 1048576:.1f} MB > '
        f'{limit / 1048576:g} MB); not read (raise it with '
        f'{MAX_FILE_MB_ENVIRONMENT_VARIABLE.name}=MEGABYTES)')


def _kind(mode):
    for test, name in (
            (stat.S_ISDIR, 'a directory'), (stat.S_ISFIFO, 'a FIFO'),
            (stat.S_ISCHR, 'a character device'),
            (stat.S_ISBLK, 'a block device'), (stat.S_ISSOCK, 'a socket')):
        if test(mode):
            return name
    return 'a special file'


def check_file(path, *, roots=None, limit=None):
    """Raise :class:`UnsafeFileError` unless ``path`` may be read.

    :param roots: directories the file's real path must be inside (with
      those of ``COLCON_RSIA_ALLOWED_ROOTS``); None: anywhere
    :param limit: the size limit in bytes (default :func:`max_file_bytes`)
    :raises OSError: also when the file does not exist
    """
    _check_root(path, roots)
    _check_stat(os.stat(path), max_file_bytes() if limit is None else limit)


def read_bytes(path, *, roots=None, limit=None):
    """The content of a checked file (see :func:`check_file`).

    :raises OSError: :class:`UnsafeFileError` for a file that is not read,
      else the error of opening or reading it
    """
    limit = max_file_bytes() if limit is None else limit
    _check_root(path, roots)
    # O_NONBLOCK: opening a FIFO with no writer must not wait for one
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_NOCTTY |
                 getattr(os, 'O_CLOEXEC', 0))
    try:
        _check_stat(os.fstat(fd), limit)
        chunks = []
        size = 0
        # files in /proc say size 0 and have content: read to the limit only
        while size <= limit:
            chunk = os.read(fd, min(1 << 20, limit + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        if size > limit:
            raise UnsafeFileError(_too_large(size, limit))
        return b''.join(chunks)
    finally:
        os.close(fd)


def read_text(path, *, roots=None, limit=None, errors='surrogateescape'):
    """The content of a checked file decoded as UTF-8."""
    return read_bytes(path, roots=roots, limit=limit).decode(
        'utf-8', errors=errors)


def unsafe_files(directory, *, roots=None, limit=None):
    """{path: reason} of the files under ``directory`` that must not be read.

    For the readers we do not control (libclang opens the headers itself):
    they get these files' names mapped to empty contents. Symlinked
    directories are not followed (as ``os.walk`` does not), but a link to
    a directory outside ``roots`` is reported.
    """
    found = {}
    roots = [directory] if roots is None else roots
    limit = max_file_bytes() if limit is None else limit
    for root, dirs, files in os.walk(directory):
        dirs[:] = [d for d in dirs if not d.startswith('.')]
        for name in files + [d for d in dirs
                             if os.path.islink(os.path.join(root, d))]:
            path = os.path.join(root, name)
            try:
                st = os.lstat(path)
                if stat.S_ISREG(st.st_mode):
                    if st.st_size > limit:
                        raise UnsafeFileError(_too_large(st.st_size, limit))
                    continue
                if stat.S_ISLNK(st.st_mode):
                    _check_root(path, roots)
                    target = os.stat(path)
                    if stat.S_ISDIR(target.st_mode):
                        continue
                    _check_stat(target, limit)
                    continue
                _check_stat(st, limit)
            except UnsafeFileError as e:
                found[path] = str(e)
            except OSError:
                continue  # a dangling link: nobody can read it
    return found


_UMASK = []


def file_mode():
    """The mode a new file gets from the umask (``mkstemp`` gives 0600)."""
    if not _UMASK:
        umask = None
        try:  # Linux: read without changing it (other threads create files)
            with open('/proc/self/status') as h:
                for line in h:
                    if line.startswith('Umask:'):
                        umask = int(line.split()[1], 8)
        except (OSError, ValueError, IndexError):
            pass
        if umask is None:
            umask = os.umask(0o022)
            os.umask(umask)
        _UMASK.append(umask)
    return 0o666 & ~_UMASK[0]


def write_text_atomically(path, text, *, errors='backslashreplace'):
    """Write a text file whole or not at all: readers see the old or the new.

    :param errors: how characters UTF-8 cannot encode (surrogate escapes
      of undecodable names) are written
    """
    def write(temporary):
        with open(temporary, 'w', encoding='utf-8', errors=errors) as h:
            h.write(text)
    write_file_atomically(path, write)


def write_json_atomically(path, data):
    """Write JSON so that readers see the old file or the new, never half.

    A temp file in the same directory is renamed over the target; a build
    killed mid-write leaves at most a stray temp file.
    """
    write_text_atomically(
        path, json.dumps(data, indent=1, sort_keys=True) + '\n')


def write_file_atomically(path, write):
    """Make a file whole or not at all: readers see the old or the new.

    ``write(temporary)`` fills a temporary file in the same directory,
    which is then renamed over the target (a write killed half-way leaves
    at most a stray temporary file, named by :func:`temporary_files_of`),
    with the mode of every other build artifact, not mkstemp's 0600.
    """
    directory = os.path.dirname(path)
    os.makedirs(directory, exist_ok=True)
    fd, temporary = tempfile.mkstemp(
        dir=directory, prefix=f'.{os.path.basename(path)}.{os.getpid()}.',
        suffix='.tmp')
    os.close(fd)
    try:
        write(temporary)
        os.chmod(temporary, file_mode())
        os.replace(temporary, path)
    except BaseException:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        raise


def temporary_files_of(directory, pid):
    """The temporary files a process killed while writing left in a directory.

    Those of :func:`write_file_atomically` (``.name.<pid>.XXXXXXXX.tmp``),
    and what a writer of its own (libclang saving a precompiled header)
    made next to them.
    """
    try:
        names = os.listdir(directory)
    except OSError:
        return []
    return sorted(
        os.path.join(directory, name) for name in names
        if name.startswith('.') and f'.{pid}.' in name and '.tmp' in name)


@contextlib.contextmanager
def directory_lock(directory):
    """Hold an exclusive lock on a directory (made if missing).

    Processes and threads that take it wait for each other (each takes it
    through its own open descriptor); the lock ends with the process that
    held it, however it ends. The directory holds no file for it. Where
    there is no ``flock`` it locks nothing.
    """
    os.makedirs(directory, exist_ok=True)
    try:
        import fcntl
    except ImportError:  # not POSIX
        yield
        return
    fd = os.open(directory, os.O_RDONLY | os.O_CLOEXEC)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)


def display(text):
    r"""A name that may hold undecodable bytes, printable and escaped.

    File names that are not UTF-8 come from ``os`` with surrogate escapes
    (``caf\\udce9``); they cannot be encoded as UTF-8, so they are shown
    with each such byte as ``\\xe9``.
    """
    if not isinstance(text, str):
        return text
    try:
        data = text.encode('utf-8', errors='surrogateescape')
    except UnicodeEncodeError:  # a lone surrogate that escapes no byte
        data = text.encode('utf-8', errors='backslashreplace')
    return data.decode('utf-8', errors='backslashreplace')


def printable(text):
    r"""Text from the analysed code as the console may show it.

    THE function every text output (console lines, listings, messages)
    passes each line or value through: control characters (``\x1b``
    escape sequences, ``\r``, a newline inside a name, C1 controls),
    bidirectional overrides and isolates (``\u202e``) and other characters
    that are not printable are shown escaped, so a name cannot clear the
    screen, set the window title, overwrite or forge a line or reorder
    what is shown. Undecodable bytes are shown as ``\xe9``
    (:func:`display`).
    """
    text = display(str(text))
    if text.isprintable():
        return text
    return ''.join(c if c.isprintable() else
                   c.encode('unicode_escape').decode('ascii') for c in text)


def printable_lines(lines):
    """Lines of text output joined, each :func:`printable`."""
    return ''.join(printable(line) + '\n' for line in lines)


# directories whose files a pull request cannot change: the include walk
# stops there (it only looks for files libclang must not open)
SYSTEM_PREFIXES = ('/usr/', '/opt/', '/lib/', '/lib64/')
_INCLUDE = re.compile(
    rb'^[ \t]*#[ \t]*(?:include|include_next|import)[ \t]*'
    rb'([<"])([^>"\r\n]+)[>"]', re.MULTILINE)
_INCLUDE_DIR_FLAGS = ('-I', '-isystem', '-iquote', '-idirafter')


def include_dirs(arguments, directory):
    """The include directories of compiler arguments, as absolute paths."""
    found = []
    arguments = list(arguments)
    for i, argument in enumerate(arguments):
        for flag in _INCLUDE_DIR_FLAGS:
            if argument == flag and i + 1 < len(arguments):
                found.append(arguments[i + 1])
            elif argument.startswith(flag) and len(argument) > len(flag):
                found.append(argument[len(flag):])
    return [os.path.normpath(os.path.join(directory, d)) for d in found]


def unsafe_inputs(sources, *, search_dirs, roots, skip=()):
    """{path: reason} of the files an include could make libclang open.

    libclang opens headers itself, and a special file or a huge one hangs
    or exhausts it: the ``#include`` lines of ``sources``, and of the
    headers they reach outside the system directories, are resolved
    (next to the including file, then in ``search_dirs``) and every
    target that is not a regular file within the size limit, or a link
    out of ``roots``, is named so that the caller can hide it (an empty
    unsaved file). Includes written as macros are not followed.

    :param skip: directory prefixes not scanned (the tool's own headers)
    """
    limit = max_file_bytes()
    roots = allowed_roots(roots)
    found = {}
    scanned = set()
    todo = [os.path.abspath(s) for s in sources]
    while todo:
        file = todo.pop()
        if file in scanned:
            continue
        scanned.add(file)
        try:
            data = read_bytes(file, limit=limit)
        except OSError:
            continue
        here = os.path.dirname(file)
        for quote, name in _INCLUDE.findall(data):
            name = os.fsdecode(name.strip())
            if os.path.isabs(name):
                candidates = [name]
            else:
                candidates = [os.path.join(d, name) for d in (
                    ([here] if quote == b'"' else []) + list(search_dirs))]
            for candidate in candidates:
                candidate = os.path.normpath(candidate)
                reason = _unsafe_target(candidate, roots, limit)
                if reason is None:
                    continue
                if reason:
                    found[candidate] = reason
                    break
                if not candidate.startswith(SYSTEM_PREFIXES + tuple(skip)):
                    todo.append(candidate)
                break  # the first directory that has it wins
    return found


def _unsafe_target(path, roots, limit):
    """None: no such file; '': a file to read; else why it must not be."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    if stat.S_ISDIR(st.st_mode):
        return None
    try:
        if os.path.islink(path) or path != os.path.realpath(path):
            real = os.path.realpath(path)
            # a link is fine within the roots, or into the system's files
            if not real.startswith(SYSTEM_PREFIXES):
                _check_root(path, roots)
        _check_stat(st, limit)
    except UnsafeFileError as e:
        return str(e)
    return ''


def unreadable_files(directory, names):
    """One line per file of ``names`` in ``directory`` that cannot be read.

    For the files whose readers stay silent when they fail (a missing
    ``CMakeLists.txt`` is normal; a link to ``/dev/zero`` is worth a word).
    """
    problems = []
    for name in names:
        path = os.path.join(directory, name)
        if not os.path.lexists(path):
            continue
        try:
            check_file(path, roots=[directory])
            read_head(path, 1)
        except OSError as e:
            problems.append(
                f'{display(name)}: {e.strerror or e}' +
                ('' if isinstance(e, UnsafeFileError) else '; not read'))
    return problems


def read_head(path, size):
    """The first ``size`` bytes of a regular file (a shebang, say)."""
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_NOCTTY |
                 getattr(os, 'O_CLOEXEC', 0))
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise UnsafeFileError(
                f'is not a regular file ({_kind(st.st_mode)}); not read')
        return os.read(fd, size)
    finally:
        os.close(fd)
