# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Parse translation units in worker processes.

libclang runs inside the process that calls it: a unit that makes it
crash (a segfault on a generated 65,000-term expression, an abort on a
full disk) would end ``colcon rsia analyze``, or the build's ``rsia+``
event handler, with it. So every unit is parsed in a worker process: a
crash, or a parse that runs past the time limit
(``COLCON_RSIA_UNIT_TIMEOUT``), loses that unit only, with one message;
the worker is replaced and the other units go on. The walk of each parse
(Python) runs in the workers too, on every core.

The workers are forked by multiprocessing's fork server (a process started
afresh, which imports the analysis once: safe from colcon's threads,
unlike a plain fork, and each worker starts in a few milliseconds), only
when a unit needs parsing (a re-analysis whose units all come from the
cache starts none), and are kept for the next package of the run.

As with any multiprocessing program, a script that calls the analysis
must guard its own code with ``if __name__ == '__main__':`` (the fork
server imports the script, as its main module, once).

Also here: how an analysis is stopped (Ctrl-C, :func:`request_stop`).
Which units are parsed, and which come from the cache: units.py.
"""

import atexit
from collections import deque
from concurrent.futures import ThreadPoolExecutor
import errno
import itertools
import multiprocessing
import multiprocessing.connection
import os
import signal
import sys
import tempfile
import threading
import time

from colcon_rsia import safe_files
from colcon_rsia.environment_variables import \
    UNIT_TIMEOUT_ENVIRONMENT_VARIABLE
from colcon_rsia.package.settings import positive_number


class Interrupted(Exception):
    """The build was interrupted: the analysis ends and writes nothing."""


# set by request_stop() when the build is interrupted (Ctrl-C)
_stop_requested = threading.Event()


def request_stop():
    """Make every running analysis end now.

    The parses under way are ended with their worker processes (in the
    thread fallback, where a parse cannot be cut short, an analysis ends
    within one translation unit's parse); the analysis writes no summary:
    the summaries already written stay whole.
    """
    _stop_requested.set()


def stop_requested():
    """Whether :func:`request_stop` was called."""
    return _stop_requested.is_set()


def check_stop():
    """Raise :class:`Interrupted` if the analysis should end now."""
    if _stop_requested.is_set():
        raise Interrupted()


def default_jobs():
    """Parallel parses: one worker process per CPU."""
    return max(1, os.cpu_count() or 1)


# the time limit of one unit unless the variable says otherwise: a ROS unit
# parses in seconds, its repair rounds take a few parses more; the 5 MB
# generated unit of tests/project/test_faults.py (90,000 functions) takes 4 minutes
# with its repairs on a busy 2-core machine, and a unit may be 8 MB (the
# file size limit). Past 15 minutes a parse does not end (a constexpr
# loop, a template explosion)
DEFAULT_UNIT_TIMEOUT_S = 900


def unit_timeout():
    """The seconds one unit may take (``COLCON_RSIA_UNIT_TIMEOUT``).

    :raises ValueError: one sentence, when the value is not a positive
      number
    """
    return positive_number(
        UNIT_TIMEOUT_ENVIRONMENT_VARIABLE.name,
        default=DEFAULT_UNIT_TIMEOUT_S, unit='seconds',
        what='the time one translation unit may take')


def unit_timeout_problem():
    """The sentence saying what is wrong with the time limit, or None."""
    try:
        unit_timeout()
    except ValueError as e:
        return str(e)
    return None


# 'forkserver': the workers are forked from a process with no threads (a
# plain fork of colcon, whose event reactor runs handlers in threads, may
# copy a lock another thread holds); None parses in threads of the calling
# process instead (no crash isolation: tests that patch the front end)
START_METHOD = 'forkserver'
# imported once by the fork server, so that every worker starts with them
# ('__main__': the colcon script, which each worker would run again)
PRELOAD = [
    '__main__', 'colcon_rsia.package.fork_server', 'clang.cindex', 'colcon_rsia.package.analysis',
    'colcon_rsia.package.workers', 'colcon_rsia.frontend.cpp',
    'colcon_rsia.frontend.cpp.model_mode',
    'colcon_rsia.frontend.cpp.model_mode.recovery',
    'colcon_rsia.frontend.cpp.parse', 'colcon_rsia.frontend.cpp.token_facts',
    'colcon_rsia.frontend.cpp.wrappers']
# how often a wait for the workers looks at request_stop(): Ctrl-C ends
# the analysis within this
POLL_S = 0.2
# how long an ended worker may take to say so, before it is killed
JOIN_S = 5.0
# a worker that crashed on SIGABRT with less free space than this where it
# writes (a precompiled header and its temporary copy take about 12 MB
# each) most likely found the disk full
LOW_DISK_BYTES = 64 << 20
# what of a crashed worker's error output its message quotes (its last line)
MAX_QUOTED_CHARS = 200

PRECOMPILING = 'precompiling'


class WorkersUnavailable(Exception):
    """No worker process can be started here (str: why)."""


def parse(function, items, *, context, jobs, timeout, cleanup_dirs=()):
    """Run ``function(item, **context)`` for every item in worker processes.

    :param function: a module-level function (the workers import it by
      name); it must not raise; its results must be picklable
    :param context: keyword arguments every call shares (sent to each
      worker once); ``precompiled_dir`` is left out when building the
      precompiled header crashed a worker
    :param int jobs: the number of worker processes
    :param float timeout: the seconds one item may take
    :param cleanup_dirs: where a worker writes files (atomically): the
      temporary files of a worker killed or crashed are removed there
    :returns: ([(True, result) or (False, what happened), one per item],
      messages about the whole package)
    :raises Interrupted: when :func:`request_stop` was called
    """
    if not items:
        return [], []
    notes = []
    if START_METHOD is not None:
        if context.get('precompiled_dir') in _failed_precompiled:
            context = dict(context, precompiled_dir=None)
        try:
            return _Run(function, context=context, jobs=jobs,
                        timeout=timeout, cleanup_dirs=cleanup_dirs).run(items)
        except WorkersUnavailable as e:
            notes.append(
                f'worker processes cannot be started ({e}): the units are '
                'parsed in threads, where a crash of libclang ends the '
                'analysis')
    return _in_threads(function, items, context, jobs), notes


def _in_threads(function, items, context, jobs):
    def work(item):
        check_stop()
        return True, function(item, **context)
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(work, items))


# precompiled header directories whose PCH crashed a worker as it was
# built: the rest of the run parses without them
_failed_precompiled = set()


class _Run:
    """The parses of one package's units."""

    _keys = itertools.count()

    def __init__(self, function, *, context, jobs, timeout, cleanup_dirs):
        self.function = function
        self.context = context
        self.jobs = max(1, jobs)
        self.timeout = timeout
        self.cleanup_dirs = [d for d in cleanup_dirs if d]
        self.key = next(self._keys)
        self.environment = _environment()
        self.niceness = _caller_niceness()
        self.notes = []

    def run(self, items):
        queue = deque((index, {}) for index in range(len(items)))
        results = [None] * len(items)
        retried = set()
        free = _checkout(min(self.jobs, len(items)), self.niceness)
        busy = []
        started = bool(free)
        try:
            while queue or busy:
                if stop_requested():
                    for worker in busy:
                        self._kill(worker)
                    busy = []
                    check_stop()
                while queue and (free or len(busy) < self.jobs):
                    if free:
                        worker = free.pop()
                    else:
                        try:
                            worker = _Worker(self.niceness)
                        except WorkersUnavailable as e:
                            if not started:
                                raise
                            if busy:
                                break  # fewer workers then
                            # none left and none starts: the rest is lost
                            while queue:
                                index, _ = queue.popleft()
                                results[index] = (
                                    False, f'no worker process starts ({e})')
                            break
                        started = True
                    index, overrides = queue.popleft()
                    if not worker.begin(self, index, items[index], overrides):
                        queue.appendleft((index, overrides))  # it was dead
                        worker.close()
                        continue
                    busy.append(worker)
                for worker, outcome in self._wait(busy):
                    busy.remove(worker)
                    if outcome is None:  # done
                        results[worker.index] = worker.result
                        worker.forward_error_output()
                        free.append(worker)
                        continue
                    what, phase = outcome
                    if phase and phase[0] == PRECOMPILING and \
                            worker.index not in retried:
                        # the precompiled header's crash, not the unit's:
                        # the unit and the rest go on without it
                        retried.add(worker.index)
                        self._without_precompiled(what)
                        queue.appendleft(
                            (worker.index, {'precompiled_dir': None}))
                    else:
                        results[worker.index] = (False, what)
        finally:
            for worker in busy:
                self._kill(worker)
            _checkin(free)
        return results, self.notes

    def _without_precompiled(self, what):
        directory = self.context.get('precompiled_dir')
        if directory is None:
            return
        _failed_precompiled.add(directory)
        self.context = dict(self.context, precompiled_dir=None)
        self.key = next(self._keys)  # the workers need the new context
        headers = 'standard' if self.context.get('package_headers') is None \
            else 'system'
        self.notes.append(
            f'the precompiled {headers} headers could not be built ({what}): '
            'units are parsed without them (slower)')

    def _wait(self, busy):
        """Wait for the busy workers; [(worker, None or (what, phase))]."""
        if not busy:
            return []
        now = time.monotonic()
        wait_s = min([POLL_S] + [w.deadline - now for w in busy])
        waited = [w.connection for w in busy] + [w.process.sentinel for w in busy]
        ready = set(multiprocessing.connection.wait(waited, max(0, wait_s)))
        ended = []
        for worker in busy:
            if worker.connection in ready:
                try:
                    message = worker.connection.recv()
                except (EOFError, OSError):
                    ended.append((worker, self._crashed(worker)))
                    continue
                if message[0] == 'phase':
                    worker.phase = message[1]
                    continue
                kind, value = message
                worker.result = (True, value) if kind == 'done' else \
                    (False, f'internal error ({value}); please report it')
                ended.append((worker, None))
            elif worker.process.sentinel in ready:
                ended.append((worker, self._crashed(worker)))
            elif time.monotonic() >= worker.deadline:
                self._kill(worker)
                ended.append((worker, (
                    f'parsing took longer than {self.timeout:g} s '
                    f'({UNIT_TIMEOUT_ENVIRONMENT_VARIABLE.name})', None)))
        return ended

    def _crashed(self, worker):
        """(what happened, its phase) of a worker that ended by itself."""
        worker.process.join(JOIN_S)
        if worker.process.exitcode is None:
            worker.process.kill()
            worker.process.join(JOIN_S)
        exitcode = worker.process.exitcode
        output = worker.new_error_output()
        phase = worker.phase
        directories = self.cleanup_dirs + (
            [os.path.dirname(phase[1])] if phase and phase[1] else [])
        full = exitcode == -signal.SIGABRT and _disk_full(output, directories)
        self._clean(worker, directories)
        worker.close()
        return crash_description(exitcode, output, disk_full=full), phase

    def _kill(self, worker):
        if worker.process.exitcode is None:
            worker.process.kill()
        worker.process.join(JOIN_S)
        directories = self.cleanup_dirs + (
            [os.path.dirname(worker.phase[1])]
            if worker.phase and worker.phase[1] else [])
        self._clean(worker, directories)
        worker.close()

    @staticmethod
    def _clean(worker, directories):
        # what it was writing when it ended (a 12 MB temporary PCH)
        for directory in dict.fromkeys(directories):
            for path in safe_files.temporary_files_of(
                    directory, worker.process.pid):
                try:
                    os.unlink(path)
                except OSError:
                    pass


def crash_description(exitcode, output='', *, disk_full=False):
    """``libclang crashed (signal SIGSEGV)``, with what it last said."""
    if exitcode is not None and exitcode < 0:
        try:
            how = f'signal {signal.Signals(-exitcode).name}'
        except ValueError:
            how = f'signal {-exitcode}'
    else:
        how = f'exit code {exitcode}'
    lines = [line.strip() for line in output.splitlines() if line.strip()]
    if lines:
        last = ''.join(c if c.isprintable() else '?' for c in lines[-1])
        if len(last) > MAX_QUOTED_CHARS:
            last = last[:MAX_QUOTED_CHARS] + '...'
        how += f': {last}'
    if disk_full:
        how += '; disk full?'
    elif exitcode == -signal.SIGKILL:
        how += '; out of memory?'  # what kills a process unasked
    return f'libclang crashed ({how})'


def _disk_full(output, directories):
    if os.strerror(errno.ENOSPC) in output:
        return True
    for directory in directories:
        try:
            stat = os.statvfs(directory)
        except OSError:
            continue
        if stat.f_bavail * stat.f_frsize < LOW_DISK_BYTES:
            return True
    return False


def _environment():
    # what the workers read (the size limit of files, the allowed roots),
    # as it is now: the fork server has the environment of its start
    return {name: value for name, value in os.environ.items()
            if name.startswith(('COLCON_RSIA_', 'RSIA_'))}


def _caller_niceness():
    # Linux: the priority of the calling thread (the build's handler lowers
    # its own); the workers take it
    try:
        return os.getpriority(os.PRIO_PROCESS, threading.get_native_id())
    except (AttributeError, OSError):
        return 0


class _Worker:
    """One worker process, seen from its parent."""

    def __init__(self, niceness):
        self.niceness = niceness
        self.context_key = None
        self.index = None
        self.phase = None
        self.deadline = None
        self.result = None
        self.error_offset = 0
        self.error_path = None
        mp = _multiprocessing_context()
        try:
            fd, self.error_path = tempfile.mkstemp(
                prefix='rsia-worker-', suffix='.stderr')
            os.close(fd)
        except OSError:
            self.error_path = None  # its errors go to ours then
        try:
            self.connection, child_end = mp.Pipe()
            self.process = mp.Process(
                target=_worker_main, name='rsia-parse', daemon=True,
                args=(child_end, self.error_path, niceness))
            try:
                self.process.start()
            finally:
                child_end.close()
        except (OSError, ValueError, EOFError, RuntimeError) as e:
            self._remove_error_file()
            raise WorkersUnavailable(f'{type(e).__name__}: {e}') from None

    def begin(self, run, index, item, overrides):
        """Send one item; False when the worker is gone."""
        self.index = index
        self.phase = None
        self.result = None
        try:
            if self.context_key != run.key:
                self.connection.send(
                    ('context', run.context, run.environment))
                self.context_key = run.key
            self.connection.send(('task', run.function, (item,), overrides))
        except (OSError, EOFError):
            return False
        self.deadline = time.monotonic() + run.timeout
        return True

    def alive(self):
        try:
            return self.process.is_alive()
        except (OSError, ValueError):
            return False

    def new_error_output(self):
        """What the worker wrote to its error output since the last look."""
        if self.error_path is None:
            return ''
        try:
            with open(self.error_path, 'rb') as h:
                h.seek(self.error_offset)
                data = h.read(1 << 16)
        except OSError:
            return ''
        self.error_offset += len(data)
        return data.decode('utf-8', errors='replace')

    def forward_error_output(self):
        output = self.new_error_output()
        if output:
            sys.stderr.write(output)
            sys.stderr.flush()

    def end(self):
        """Tell an idle worker to end; :meth:`close` waits for it."""
        try:
            self.connection.send(None)
        except (OSError, EOFError, ValueError):
            pass

    def close(self):
        """Wait for the ended worker (kill it if it is not); free all."""
        self.process.join(JOIN_S)
        if self.process.exitcode is None:
            self.process.kill()
            self.process.join(JOIN_S)
        self.connection.close()
        self._remove_error_file()

    def _remove_error_file(self):
        if self.error_path is not None:
            try:
                os.unlink(self.error_path)
            except OSError:
                pass
            self.error_path = None


_multiprocessing = []


_context_lock = threading.Lock()


def _multiprocessing_context():
    with _context_lock:
        if not _multiprocessing:
            context = multiprocessing.get_context(START_METHOD)
            if START_METHOD == 'forkserver':
                context.set_forkserver_preload(PRELOAD)
                _start_fork_server()
            _multiprocessing.append(context)
    return _multiprocessing[0]


def _start_fork_server():
    """Start the fork server with no terminal to print to.

    Ctrl-C reaches the whole process group, the fork server too, and it
    ignores Ctrl-C only from its first preloaded import (fork_server.py):
    one pressed while its interpreter starts printed a traceback under
    colcon's output. Its stderr (and that of the workers it forks, which
    write theirs to their own files) is /dev/null: fd 2 points there for
    the moment the server is spawned, which inherits it.
    """
    import multiprocessing.forkserver
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        saved = os.dup(2)
    except OSError:
        return  # (started with our stderr by the first worker then)
    try:
        os.dup2(devnull, 2)
        multiprocessing.forkserver.ensure_running()
    except (OSError, ValueError, RuntimeError):
        pass  # the first worker's start says why, with our stderr back
    finally:
        os.dup2(saved, 2)
        os.close(saved)
        os.close(devnull)


# idle workers, for the next package of the run
_idle = []
_idle_lock = threading.Lock()


def _checkout(count, niceness):
    with _idle_lock:
        mine = [w for w in _idle if w.niceness == niceness][:count]
        for worker in mine:
            _idle.remove(worker)
    alive = []
    for worker in mine:
        if worker.alive():
            alive.append(worker)
        else:
            worker.close()
    return alive


def _checkin(workers):
    with _idle_lock:
        _idle.extend(workers)


def shutdown():
    """End the idle workers (the end of a build or of a command)."""
    with _idle_lock:
        workers = list(_idle)
        _idle.clear()
    for worker in workers:
        worker.end()
    for worker in workers:
        worker.close()


atexit.register(shutdown)


# --- in the worker process --------------------------------------------------

def _worker_main(connection, error_path, niceness):
    """Run the items the parent sends, one at a time, until it says end."""
    # Ctrl-C reaches the whole process group: the parent decides what ends
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        if niceness > os.getpriority(os.PRIO_PROCESS, 0):
            os.setpriority(os.PRIO_PROCESS, 0, niceness)
    except (AttributeError, OSError):
        pass
    if error_path is not None:
        # libclang's last words ("LIBCLANG FATAL ERROR: ...") are read from
        # here into the message of a crash
        fd = os.open(error_path, os.O_WRONLY | os.O_APPEND)
        os.dup2(fd, 2)
        os.close(fd)
    from colcon_rsia.frontend.cpp.model_mode import precompiled

    def on_build(path):
        connection.send(('phase', (PRECOMPILING, path) if path else None))
    # (both modes' precompiled headers say so through it)
    precompiled.on_build = on_build
    context = {}
    while True:
        try:
            message = connection.recv()
        except (EOFError, OSError):
            return  # the parent is gone
        if message is None:
            return
        if message[0] == 'context':
            _, context, environment = message
            _set_environment(environment)
            continue
        _, function, args, overrides = message
        try:
            reply = ('done', function(*args, **dict(context, **overrides)))
        except Exception as e:  # noqa: B902
            reply = ('error', f'{type(e).__name__}: {e}')
        try:
            connection.send(reply)
        except (OSError, EOFError):
            return
        except Exception as e:  # noqa: B902
            # a result that cannot be pickled (sent nothing yet)
            connection.send(('error', f'{type(e).__name__}: {e}'))


def _set_environment(environment):
    for name in list(os.environ):
        if name.startswith(('COLCON_RSIA_', 'RSIA_')) and \
                name not in environment:
            del os.environ[name]
    os.environ.update(environment)
