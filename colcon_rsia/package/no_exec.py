# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Run one program that can start no other: ``python no_exec.py PROG ARGS``.

Run inside the sandbox of :mod:`colcon_rsia.package.sandbox`, before any
code of the analysed workspace: it installs a seccomp filter under which
``execve`` and ``execveat`` fail (EPERM), except one ``execveat`` of the
descriptor it opened on PROG, and starts PROG through that descriptor. The
descriptor closes as PROG starts (close-on-exec), so PROG and everything it
does can start no program at all: CMake interprets the package's CMake
code, and every ``execute_process()``, ``try_run()``, compiler, ``git`` or
script it asks for fails to start, whatever the code does.

Standalone on purpose (only the standard library): it runs with ``-I -S``
in a sandbox that holds the interpreter's standard library and nothing of
colcon-rsia but this file. Exits 126 with a message when the filter cannot
be installed (the caller then treats the sandbox as unavailable).
"""

import ctypes
import os
import platform
import sys

# (AUDIT_ARCH_*, execve, execveat) of the architectures whose numbers are
# known here; on any other the program is not started
ARCHITECTURES = {
    'x86_64': (0xC000003E, 59, 322),
    'aarch64': (0xC00000B7, 221, 281),
}
# x86_64's x32 ABI: the same calls with this bit set
X32_SYSCALL_BIT = 0x40000000
AT_EMPTY_PATH = 0x1000
PR_SET_NO_NEW_PRIVS = 38
PR_SET_SECCOMP = 22
SECCOMP_MODE_FILTER = 2
SECCOMP_RET_ALLOW = 0x7FFF0000
SECCOMP_RET_ERRNO = 0x00050000
EPERM = 1
# classic BPF opcodes
LD_W_ABS = 0x20
JEQ_K = 0x15
JGE_K = 0x35
RET_K = 0x06
# offsets in struct seccomp_data: nr, arch, args[6] (64-bit each; the low
# half first on these little-endian machines)
NR = 0
ARCH = 4
ARGS = 16
# the descriptor PROG is started from: above any the sandbox passes on
PROGRAM_FD = 1023
EXIT_NOT_STARTED = 126


class SockFilter(ctypes.Structure):
    """struct sock_filter."""

    _fields_ = [('code', ctypes.c_ushort), ('jt', ctypes.c_ubyte),
                ('jf', ctypes.c_ubyte), ('k', ctypes.c_uint)]


class SockFprog(ctypes.Structure):
    """struct sock_fprog."""

    _fields_ = [('len', ctypes.c_ushort),
                ('filter', ctypes.POINTER(SockFilter))]


def filter_program(machine, program_fd):
    """The BPF instructions (code, jt, jf, k) of the filter."""
    audit_arch, execve, execveat = ARCHITECTURES[machine]
    deny = SECCOMP_RET_ERRNO | EPERM
    # jumps count the instructions skipped; the last two are the returns
    program = [
        (LD_W_ABS, 0, 0, ARCH),
        (JEQ_K, 1, 0, audit_arch),          # another ABI (int 0x80): deny
        (RET_K, 0, 0, deny),
        (LD_W_ABS, 0, 0, NR),
        (JGE_K, 0, 1, X32_SYSCALL_BIT),     # x32 calls: deny
        (RET_K, 0, 0, deny),
        (JEQ_K, 0, 1, execve),
        (RET_K, 0, 0, deny),
        (JEQ_K, 1, 0, execveat),
        (RET_K, 0, 0, SECCOMP_RET_ALLOW),
        # execveat: only of our descriptor, with an empty path
        (LD_W_ABS, 0, 0, ARGS),
        (JEQ_K, 0, 5, program_fd),
        (LD_W_ABS, 0, 0, ARGS + 4),
        (JEQ_K, 0, 3, 0),
        (LD_W_ABS, 0, 0, ARGS + 4 * 8),     # args[4]: the flags
        (JEQ_K, 0, 1, AT_EMPTY_PATH),
        (RET_K, 0, 0, SECCOMP_RET_ALLOW),
        (RET_K, 0, 0, deny),
    ]
    return program


def _install_filter(libc, machine):
    program = filter_program(machine, PROGRAM_FD)
    instructions = (SockFilter * len(program))(
        *(SockFilter(*i) for i in program))
    fprog = SockFprog(len(program), instructions)
    if libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 or \
            libc.prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER,
                       ctypes.byref(fprog), 0, 0) != 0:
        raise OSError(ctypes.get_errno(), os.strerror(ctypes.get_errno()))


def _strings(values):
    array = (ctypes.c_char_p * (len(values) + 1))()
    for i, value in enumerate(values):
        array[i] = os.fsencode(value)
    array[len(values)] = None
    return array


def main(argv):
    """Start argv[1:] unable to start anything; return on failure only."""
    if len(argv) < 2:
        print('usage: no_exec.py PROGRAM [ARGUMENTS]', file=sys.stderr)
        return 2
    machine = platform.machine()
    if machine not in ARCHITECTURES:
        print(f'no_exec: the system calls of {machine} are not known',
              file=sys.stderr)
        return EXIT_NOT_STARTED
    libc = ctypes.CDLL(None, use_errno=True)
    try:
        fd = os.open(argv[1], os.O_PATH | os.O_CLOEXEC)
        if fd != PROGRAM_FD:
            os.dup2(fd, PROGRAM_FD, inheritable=False)
            os.close(fd)
        _install_filter(libc, machine)
    except OSError as e:
        print(f'no_exec: {e}', file=sys.stderr)
        return EXIT_NOT_STARTED
    _, _, execveat = ARCHITECTURES[machine]
    libc.syscall.restype = ctypes.c_long
    libc.syscall(ctypes.c_long(execveat), ctypes.c_int(PROGRAM_FD),
                 ctypes.c_char_p(b''), _strings(argv[1:]),
                 _strings([f'{k}={v}' for k, v in os.environ.items()]),
                 ctypes.c_int(AT_EMPTY_PATH))
    print(f'no_exec: {argv[1]}: '
          f'{os.strerror(ctypes.get_errno())}', file=sys.stderr)
    return EXIT_NOT_STARTED


if __name__ == '__main__':
    sys.exit(main(sys.argv))
