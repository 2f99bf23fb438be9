# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Imported first by the workers' fork server: Ctrl-C is ignored from then.

multiprocessing's fork server ignores Ctrl-C only once it has imported
its preloaded modules (libclang and the analysis, a second or more); Ctrl-C
reaches the whole process group, so one pressed meanwhile printed the fork
server's traceback under colcon's output. The parent decides what a
Ctrl-C ends (see workers.py); this import, the first of the preload list,
makes the fork server ignore it from the start. Nothing happens when
another process imports the module.
"""

import signal
import sys


def _in_fork_server():
    # the fork server runs `python -c "from multiprocessing.forkserver
    # import main; main(...)"`; no colcon process is started with -c
    return sys.argv[:1] == ['-c'] and 'multiprocessing.forkserver' in sys.modules


if _in_fork_server():
    signal.signal(signal.SIGINT, signal.SIG_IGN)
