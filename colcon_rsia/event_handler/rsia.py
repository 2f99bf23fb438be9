# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0

from concurrent.futures import ThreadPoolExecutor
import os
import signal
import threading
import time

from colcon_core.event.job import JobEnded
from colcon_core.event.timer import TimerEvent
from colcon_core.event_handler import EventHandlerExtensionPoint
from colcon_core.event_reactor import EventReactorShutdown
from colcon_core.plugin_system import satisfies_version
from colcon_core.subprocess import SIGINT_RESULT


class RsiaEventHandler(EventHandlerExtensionPoint):
    """
    Analyse each package's rates right after its build job ends.

    The analysis runs in a worker thread while the build goes on (its
    translation units parsed in worker processes: a unit that crashes
    libclang loses only itself); results are printed as they come and
    joined when the build ends. A package that cannot be analysed gets one
    message and never fails the build.
    """

    # the build's own console output and logs come first (they have higher
    # priorities); our lines follow the package's "Finished" line
    PRIORITY = 60

    # packages analysed at once: libclang parsing is CPU-bound and the build
    # still needs the cores, so one package at a time, its translation units
    # parsed in parallel
    PACKAGE_WORKERS = 1

    # the niceness of the analysis threads: the compiler comes first, the
    # analysis takes the CPU time the build leaves (the worker processes
    # that parse its units take it too)
    NICENESS = 10

    def __init__(self):  # noqa: D107
        super().__init__()
        satisfies_version(
            EventHandlerExtensionPoint.EXTENSION_POINT_VERSION, '^1.0')
        # instantiated on every colcon call, --help included: stay cheap
        self.enabled = False
        self._pool = None
        self._pending = []
        self._outcomes = []
        self._packages = None
        self._interrupted = False
        # a bad environment variable: said once, nothing analysed
        self._refused = False

    def __call__(self, event):  # noqa: D102
        data = event[0]
        if self.context is None or \
                getattr(self.context.args, 'verb_name', None) != 'build':
            return
        if isinstance(data, JobEnded):
            job = event[1]
            if _is_interrupt(data.rc):
                self._interrupt()
            elif str(data.rc) == '0' and job is not None and \
                    not self._interrupted:
                self._submit(job)
        elif isinstance(data, TimerEvent):
            self._report_finished()
        elif isinstance(data, EventReactorShutdown):
            self._shutdown()

    def _submit(self, job):
        # imported here: the analysis (and libclang) loads only when used
        from colcon_rsia.package.environment import environment_problems
        from colcon_rsia.package.runner import analyze
        pkg = job.task_context.pkg
        args = job.task_context.args
        if self._refused:
            return
        if self._pool is None:
            problems = environment_problems()
            if problems:
                # the build goes on; the analysis would use wrong settings
                self._refused = True
                from colcon_rsia.safe_files import printable
                for problem in problems:
                    print(printable(f'rsia: {problem}; no package is '
                                    'analysed'), flush=True)
                return
            _stop_before_exit()
            self._pool = ThreadPoolExecutor(
                max_workers=self.PACKAGE_WORKERS,
                thread_name_prefix='rsia', initializer=self._lower_priority)
        self._pending.append(self._pool.submit(
            analyze, name=pkg.name, package_type=pkg.type,
            path=str(pkg.path), build_base=args.build_base,
            cmake_args=getattr(args, 'cmake_args', None),
            workspace_package_dirs=self._workspace_package_dirs(pkg),
            dependencies=self._dependencies(job)))

    def _interrupt(self):
        # Ctrl-C: colcon stops its jobs; analyse nothing more, and end the
        # analysis under way (its worker processes) without writing, so
        # that colcon exits as soon as its own jobs have stopped
        from colcon_rsia.package.workers import request_stop
        self._interrupted = True
        request_stop()
        for future in self._pending:
            future.cancel()  # those not started yet

    def _workspace_packages(self):
        # discovered once, on the first package analysed, with the build's
        # own arguments
        from colcon_rsia.package.runner import workspace_packages
        if self._packages is None:
            try:
                self._packages = workspace_packages(self.context.args)
            except Exception:  # noqa: B902
                # discovery has already succeeded once for this build; if
                # it fails now, each package still has its own headers
                self._packages = {}
        return self._packages

    def _workspace_package_dirs(self, pkg):
        return sorted({path for _, path in self._workspace_packages().values()}
                      | {os.path.abspath(str(pkg.path))})

    def _dependencies(self, job):
        # the workspace's packages the job's package depends on
        # (recursively), as colcon ordered the build by them
        packages = self._workspace_packages()
        names = getattr(job.task_context, 'dependencies', None) or {}
        return [(name, *packages[name]) for name in names if name in packages]

    @classmethod
    def _lower_priority(cls):
        # Linux: the priority of a thread id is that thread's alone; the
        # niceness is added to the build's (setting it outright would raise
        # the priority of a build already run with `nice`)
        try:
            thread = threading.get_native_id()
            niceness = os.getpriority(os.PRIO_PROCESS, thread)
            os.setpriority(os.PRIO_PROCESS, thread,
                           min(19, niceness + cls.NICENESS))
        except (AttributeError, OSError):
            pass  # elsewhere the analysis runs at the build's priority

    def _report_finished(self):
        still_running = []
        for future in self._pending:
            if future.done():
                self._report(future)
            else:
                still_running.append(future)
        self._pending = still_running

    def _report(self, future):
        from colcon_rsia.package.runner import Outcome
        if future.cancelled():
            return
        try:
            outcome = future.result()
        except Exception as e:  # noqa: B902
            outcome = Outcome('?', error=str(e))
        self._outcomes.append(outcome)
        if not outcome.skipped:
            print(outcome.line(), flush=True)

    def _shutdown(self):
        from colcon_rsia.package import workers
        if self._pool is None:
            return
        # every build job has ended: from here on, the build waits for us
        waiting_since = time.monotonic()
        for future in self._pending:
            self._report(future)  # waits for the analysis to end
        self._pending = []
        self._pool.shutdown(wait=True)
        self._pool = None
        # the processes that parsed the units end with the build
        workers.shutdown()
        analysed = [o for o in self._outcomes if o.summary is not None]
        considered = [o for o in self._outcomes if not o.skipped]
        nodes = sum(len(o.summary.nodes) for o in analysed)
        if self._interrupted or workers.stop_requested():
            print(
                f'rsia: interrupted; analysed {len(analysed)} packages '
                f'({nodes} nodes) before that, the others not: build again '
                "or run 'colcon rsia analyze'", flush=True)
            return
        # the packages' own analysis time, not the time since the first
        # package's job ended: most of that is the build of the others,
        # which the analysis runs beside
        work = sum(o.summary.seconds for o in analysed)
        print(
            f'rsia: analysed {len(analysed)} of {len(considered)} '
            f'packages ({nodes} nodes): {work:.1f}s of analysis, the build '
            f'waited {time.monotonic() - waiting_since:.1f}s for it; '
            "see 'colcon rsia graph' and 'colcon rsia impact'", flush=True)
        from colcon_rsia.package.shared_cache import statistics_line
        if statistics_line():
            print(statistics_line(), flush=True)
        if not analysed:
            return
        from colcon_rsia.package.coverage import workspace_report
        from colcon_rsia.render.coverage import total_line
        print(total_line(workspace_report(
            [o.summary for o in analysed],
            {o.package: o.error for o in self._outcomes
             if o.error is not None})), flush=True)


def _is_interrupt(rc):
    # what colcon's executors give the jobs they stop on Ctrl-C, or the
    # result of a job whose process Ctrl-C reached first (killed by SIGINT:
    # -2); not the number 2, which make returns for a failed build
    return rc == SIGINT_RESULT or str(rc) == str(-signal.SIGINT)


def _stop_before_exit():
    # Ctrl-C while colcon waits for the analysis at the end of the build:
    # colcon returns, and the interpreter joins our threads before it exits.
    # The functions threading runs just before that join end the analysis
    # (its parses in worker processes). (A private hook, the one concurrent.futures uses;
    # where it is missing, the analysis under way runs to its end.)
    from colcon_rsia.package.workers import request_stop
    register = getattr(threading, '_register_atexit', None)
    if register is not None:
        try:
            register(request_stop)
        except RuntimeError:
            pass  # the interpreter is already exiting
