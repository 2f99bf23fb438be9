# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Where the code of an analysed workspace is interpreted: a sandbox.

colcon-rsia runs one program on a workspace's code: CMake, to list the
targets of an unbuilt package (:mod:`colcon_rsia.package.cmake_configure`).
It runs in a bubblewrap (``bwrap``) sandbox:

- no network, no other process, no capability (``--unshare-all``,
  ``--cap-drop ALL``), a session of its own (``--new-session``: it cannot
  type into the user's terminal), killed with its caller
  (``--die-with-parent``);
- an environment of ``PATH``, ``HOME`` (the writable directory) and
  ``LANG`` only;
- a file system of only what it needs, read-only: the program, the shared
  libraries it loads, the data it names, the package; writable: one
  directory; ``/dev``, ``/proc`` and a small ``/tmp`` of its own. The
  user's home, ``/etc`` and the rest of the machine are not there to be
  read;
- started by ``no_exec.py`` (see there), so that it can start no other
  program: every ``execve`` fails.

:func:`sandbox_problem` says why a sandbox cannot be made here (no
``bwrap``, no user namespaces, no seccomp); the caller then does not run
the program (unless the user says so).
"""

import os
import re
import shutil
import subprocess
import sys
import threading

NO_EXEC = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                       'no_exec.py')
# the environment inside: nothing of the user's
PATH = '/usr/bin:/bin'
LANGUAGE = 'C'
# ldd, once per program: it only lists libraries
LDD_TIMEOUT_S = 30
# a sandbox that cannot start a program in this time does not work here
PROBE_TIMEOUT_S = 30
# its /tmp is memory: CMake writes nothing there that needs more
TMP_SIZE_BYTES = 64 * 1024 ** 2


def bwrap_executable():
    """The path of ``bwrap``, or None."""
    return shutil.which('bwrap')


def shared_libraries(executable):
    """The files the dynamic loader maps to run `executable`.

    Its libraries and the loader, as ``ldd`` lists them (a program that is
    not dynamically linked needs none).

    :raises OSError: when a library is missing or ldd cannot be run
    """
    ldd = shutil.which('ldd') or '/usr/bin/ldd'
    try:
        result = subprocess.run(
            [ldd, executable], capture_output=True, text=True,
            timeout=LDD_TIMEOUT_S, env={'LC_ALL': 'C', 'PATH': PATH})
    except (OSError, subprocess.SubprocessError) as e:
        raise OSError(f'ldd could not be run ({e})') from None
    output = result.stdout + result.stderr
    if 'not a dynamic executable' in output or 'statically linked' in output:
        return []
    if result.returncode != 0:
        raise OSError(f'ldd {executable} failed: {output.strip()[:200]}')
    missing = re.findall(r'^\s*(\S+) => not found', output, re.MULTILINE)
    if missing:
        raise OSError(f"{executable} needs {', '.join(missing)}, which "
                      'is not found')
    return sorted(set(re.findall(
        r'(?:=>\s*|^\s*)(/\S+)\s+\(0x', output, re.MULTILINE)))


def interpreter():
    """The Python interpreter that runs ``no_exec.py``: a real file.

    A virtual environment's ``python`` is a link or a copy that finds its
    standard library through ``pyvenv.cfg``: its base interpreter is run.
    """
    return os.path.realpath(
        getattr(sys, '_base_executable', None) or sys.executable)


_NO_EXEC_VIEW = []
_NO_EXEC_VIEW_LOCK = threading.Lock()


def no_exec_view():
    """What ``no_exec.py`` needs to run: the interpreter and its library.

    :raises OSError: when a part cannot be found
    """
    with _NO_EXEC_VIEW_LOCK:
        if not _NO_EXEC_VIEW:
            import _ctypes
            python = interpreter()
            # the standard library and its extension modules (not a
            # virtual environment's site-packages)
            view = {python, NO_EXEC, os.path.dirname(os.__file__),
                    os.path.dirname(_ctypes.__file__)}
            view.update(shared_libraries(python))
            view.update(shared_libraries(_ctypes.__file__))
            _NO_EXEC_VIEW.append(sorted(view))
        return _NO_EXEC_VIEW[0]


def loader_cache():
    """The dynamic loader's cache (paths only), when the system has one."""
    return [p for p in ('/etc/ld.so.cache',) if os.path.isfile(p)]


def no_exec_command(command):
    """``command`` started by ``no_exec.py``: it can start no program."""
    return [interpreter(), '-I', '-S', NO_EXEC] + list(command)


def sandboxed_command(command, *, read_only, writable, read_only_inside=()):
    """The argv running ``command`` in a bubblewrap sandbox.

    :param command: the program (an absolute path in ``read_only``) and
      its arguments; it is started by ``no_exec.py``
    :param read_only: the host paths it sees, read-only, at their paths
      (the program, its libraries, its data, the input)
    :param writable: the one directory it may write: also its ``HOME``
      and working directory
    :param read_only_inside: paths under ``writable`` it may not change
    :raises OSError: when what ``no_exec.py`` needs cannot be found
    """
    argv = [bwrap_executable() or 'bwrap',
            '--unshare-all', '--die-with-parent', '--new-session',
            '--cap-drop', 'ALL', '--clearenv',
            '--setenv', 'PATH', PATH, '--setenv', 'HOME', writable,
            '--setenv', 'LANG', LANGUAGE, '--setenv', 'LC_ALL', LANGUAGE,
            '--dev', '/dev', '--proc', '/proc',
            '--size', str(TMP_SIZE_BYTES), '--tmpfs', '/tmp']
    for path in sorted(set(read_only) | set(no_exec_view()) |
                       set(loader_cache())):
        argv += ['--ro-bind', path, path]
    argv += ['--bind', writable, writable]
    for path in read_only_inside:
        argv += ['--ro-bind', path, path]
    # the root bubblewrap assembles the binds in is memory: not written
    argv += ['--remount-ro', '/', '--chdir', writable, '--']
    return argv + no_exec_command(command)


_PROBED = {}
_PROBE_LOCK = threading.Lock()


def sandbox_problem(program, read_only, scratch):
    """Why ``program --version`` cannot run in the sandbox here, or None.

    Asked once per process and program.

    :param read_only: what the program needs (see :func:`sandboxed_command`)
    :param scratch: an existing directory the probe may use
    """
    with _PROBE_LOCK:
        if program not in _PROBED:
            _PROBED[program] = _probe(program, read_only, scratch)
        return _PROBED[program]


def _probe(program, read_only, scratch):
    if bwrap_executable() is None:
        return 'bubblewrap (bwrap) is not installed'
    try:
        command = sandboxed_command([program, '--version'],
                                    read_only=read_only, writable=scratch)
    except (OSError, ImportError) as e:
        return f'the sandbox cannot be assembled ({e})'
    try:
        result = subprocess.run(
            command,
            stdin=subprocess.DEVNULL, capture_output=True, text=True,
            errors='replace', timeout=PROBE_TIMEOUT_S)
    except (OSError, subprocess.SubprocessError) as e:
        return f'bubblewrap could not be run ({e})'
    if result.returncode != 0:
        said = (result.stderr.strip() or result.stdout.strip()).splitlines()
        return 'bubblewrap cannot make a sandbox here (' + \
            (said[0][:200] if said else f'exit {result.returncode}') + ')'
    return None
