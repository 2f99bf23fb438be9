# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Which executables a CMake package makes, as CMake itself says.

A built package has CMake's file-API codemodel in its build directory
(colcon-cmake asks for it). An unbuilt one is configured here by the real
``cmake``, in a directory of its own under ``<build base>/rsia/cmake_configure``,
with ``ros_stand_ins.cmake`` standing in for ROS (which need not be
installed): every ``find_package`` succeeds with nothing in it, and the
commands ROS packages bring do nothing, except those that make targets or
register components. Only CMake's configure runs, in the sandbox of
:mod:`colcon_rsia.package.sandbox` (no program starts, nothing outside that
directory is written or read but the package and CMake itself, no
network), with a time limit; its result is kept, keyed by the package's
CMake files, so an unchanged package is configured once. A result that
may not repeat (a time-out, a full disk) is not kept.

When CMake cannot be asked (no ``cmake``, one older than 3.24, no sandbox,
a configure that fails), :func:`configure_package` says why in one sentence
and the caller reads ``CMakeLists.txt`` itself.
"""

from dataclasses import dataclass
from dataclasses import field
import glob
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import tempfile
import threading
import time
from typing import Optional

from colcon_rsia import __version__
from colcon_rsia import safe_files
from colcon_rsia.environment_variables import \
    CMAKE_WITHOUT_SANDBOX_ENVIRONMENT_VARIABLE
from colcon_rsia.package import sandbox
from colcon_rsia.package import shared_cache
from colcon_rsia.summary import store

# the dependency provider (cmake_language(SET_DEPENDENCY_PROVIDER)) came
# with CMake 3.24
MINIMUM_CMAKE_VERSION = (3, 24)
# one package's configure: a legitimate one takes well under a second
CONFIGURE_TIMEOUT_S = 60
# all configures of one run (one process, one build base) together: CMake
# code that loops forever in every package of a pull request costs this,
# not a minute per package. About a thousand legitimate configures fit.
CONFIGURE_BUDGET_S = 300
SCRATCH_DIRNAME = 'cmake_configure'
RESULT_FILENAME = 'result.json'
STAND_INS = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                         'ros_stand_ins.cmake')
FALLBACK = 'CMakeLists.txt read by the fallback reader'
# the compiler CMake is told the package has: nothing is compiled, and
# CMake's modules and packages choose flags by compiler (GNU is the usual)
STAND_IN_COMPILER_ID = 'GNU'
STAND_IN_COMPILER_VERSION = '12.2.0'
# each configure's own directory in the scratch directory
RUN_PREFIX = 'run-'
CXX_SOURCE_EXTENSIONS = ('.cpp', '.cc', '.cxx', '.c++', '.c')
# directories of a package that hold no CMake code of its own
_NOT_PACKAGE_CMAKE = frozenset({'build', 'install', 'devel', 'log'})


@dataclass
class Configured:
    """What configuring a package told, or why it could not be asked."""

    # {executable name: [absolute source paths]}; None: not configured
    executables: Optional[dict] = None
    # ('node', plugin class, executable or '') and ('nodes', class) of
    # rclcpp_components_register_node(s), in the order they ran
    registrations: list = field(default_factory=list)
    # why CMake was not asked or failed (one diagnostic), else None
    problem: Optional[str] = None


def is_cxx_source(path):
    """Whether a file is C or C++ source a target compiles."""
    return os.path.splitext(path)[1].lower() in CXX_SOURCE_EXTENSIONS


def executables_from_codemodel(cmake_build_dir):
    """{executable: [sources]} of a CMake build directory's codemodel.

    Every target of type EXECUTABLE with C/C++ sources, named as on disk
    (``OUTPUT_NAME``) when it says so. None when the directory holds no
    readable codemodel reply.
    """
    indexes = sorted(glob.glob(os.path.join(
        cmake_build_dir, '.cmake', 'api', 'v1', 'reply', 'index-*.json')))
    if not indexes:
        return None
    reply_dir = os.path.dirname(indexes[-1])
    try:
        with open(indexes[-1]) as h:
            index = json.load(h)
        codemodel_file = None
        for client in index.get('reply', {}).values():
            if isinstance(client, dict) and 'codemodel-v2' in client:
                codemodel_file = client['codemodel-v2']['jsonFile']
        if codemodel_file is None:
            return None
        with open(os.path.join(reply_dir, codemodel_file)) as h:
            codemodel = json.load(h)
        source_dir = codemodel['paths']['source']
        targets = {}
        for configuration in codemodel['configurations'][:1]:
            for target in configuration['targets']:
                with open(os.path.join(reply_dir, target['jsonFile'])) as h:
                    targets[target['id']] = json.load(h)
    except (OSError, ValueError, KeyError, TypeError):
        return None
    executables = {}
    for target in targets.values():
        if target.get('type') != 'EXECUTABLE':
            continue
        # generated sources (moc's, a parameter library's) are the build's,
        # not code of the package
        sources = [
            os.path.normpath(os.path.join(source_dir, s['path']))
            for s in target.get('sources', [])
            if 'path' in s and not s.get('isGenerated')]
        sources = [s for s in sources if is_cxx_source(s)]
        if not sources:
            continue
        name = target.get('nameOnDisk') or target['name']
        executables[name] = sources
    return executables


_CMAKE_VERSION = []
_CMAKE_VERSION_LOCK = threading.Lock()


def cmake_version():
    """(cmake path, (major, minor) or None), asked once per process."""
    with _CMAKE_VERSION_LOCK:
        if not _CMAKE_VERSION:
            _CMAKE_VERSION.append(_ask_cmake_version())
        return _CMAKE_VERSION[0]


def _ask_cmake_version():
    cmake = shutil.which('cmake')
    if cmake is None:
        return None, None
    try:
        output = subprocess.run(
            [cmake, '--version'], capture_output=True, text=True,
            timeout=30, env=_configure_environment()).stdout
    except (OSError, subprocess.SubprocessError):
        return cmake, None
    match = re.search(r'version (\d+)\.(\d+)', output)
    return cmake, (int(match.group(1)), int(match.group(2))) \
        if match else None


def configure_package(package_path, build_base):
    """Configure an unbuilt package with CMake, once per content.

    :param package_path: the package's source directory
    :param build_base: the package's build directory (its scratch directory
      ``rsia/cmake_configure`` is ours)
    :rtype: Configured
    """
    package_path = os.path.abspath(package_path)
    cmake_files = _package_cmake_files(package_path)
    if 'CMakeLists.txt' not in cmake_files:
        return Configured()  # nothing to configure: nothing to say
    for relative, content in sorted(cmake_files.items()):
        try:
            content.decode('utf-8')
        except UnicodeDecodeError:
            # CMake reads it, but writes the file names it holds garbled
            # into the codemodel (a Latin-1 'café.cpp' loses its '.cpp')
            return Configured(problem=(
                f'{relative} is not UTF-8, which CMake cannot report file '
                f'names of; {FALLBACK}'))
    cmake, version = cmake_version()
    if cmake is None:
        return Configured(problem=f'cmake was not found; {FALLBACK}')
    if version is None:
        return Configured(
            problem=f'the version of {cmake} could not be read; {FALLBACK}')
    if version < MINIMUM_CMAKE_VERSION:
        return Configured(problem=(
            f'CMake {version[0]}.{version[1]} is older than 3.24, which '
            f'CMake needs to stand in for find_package(); {FALLBACK}'))
    scratch = os.path.join(build_base, store.RSIA_DIRNAME, SCRATCH_DIRNAME)
    key = _content_key(cmake_files, version)
    result_file = os.path.join(scratch, RESULT_FILENAME)
    cached = _read_result(result_file, key)
    if cached is not None:
        return cached
    # the key is the content of the package's CMake code, wherever it is:
    # another clone's result serves (its sources named by placeholders)
    shared = shared_cache.SharedCache.of_package(package_path, build_base)
    found = shared.lookup_result('cmake', key) if shared else None
    if found is not None:
        cached = _result(dict(found, key=key), key)
        if cached is not None:
            _keep(result_file, key, cached)
            return cached
    with _NOT_KEPT_LOCK:
        if (scratch, key) in _NOT_KEPT:
            # asked again for the same package in this run: the same answer
            return _NOT_KEPT[(scratch, key)]
    configured, lasting = _configure_in_run_directory(
        cmake, package_path, scratch, cmake_files, build_base)
    if not lasting:
        with _NOT_KEPT_LOCK:
            _NOT_KEPT[(scratch, key)] = configured
        return configured
    data = _keep(result_file, key, configured)
    if shared is not None:
        shared.store_result('cmake', key, data)
    return configured


def _keep(result_file, key, configured):
    data = {'key': key, 'executables': configured.executables,
            'registrations': configured.registrations,
            'problem': configured.problem}
    try:
        safe_files.write_json_atomically(result_file, data)
    except OSError:
        pass  # a result that cannot be kept only costs time
    return data


# results that may not repeat (a time-out under load, a full disk, no
# sandbox): never written under the content key, but kept for this run so
# that one package is not configured again by each of its readers
_NOT_KEPT = {}
_NOT_KEPT_LOCK = threading.Lock()
# {workspace build base: seconds of configure spent in this process}
_BUDGET_USED = {}
_BUDGET_LOCK = threading.Lock()


def without_sandbox_allowed():
    """Whether the user allows CMake to run where no sandbox can be made."""
    return os.environ.get(
        CMAKE_WITHOUT_SANDBOX_ENVIRONMENT_VARIABLE.name, '') == '1'


def _configure_in_run_directory(cmake, package_path, scratch, cmake_files,
                                build_base):
    """(Configured, whether it may be kept) of one configure.

    Each configure has a directory of its own (two analyses of a package
    at once never share one) and removes it when done.
    """
    workspace = os.path.dirname(os.path.abspath(build_base))
    with _BUDGET_LOCK:
        left = CONFIGURE_BUDGET_S - _BUDGET_USED.get(workspace, 0.0)
    if left <= 0:
        return Configured(problem=(
            f'the CMake configures of this run took {CONFIGURE_BUDGET_S} s '
            f'together, all the time they have; {FALLBACK}')), False
    try:
        os.makedirs(scratch, exist_ok=True)
        _remove_abandoned_runs(scratch)
        run = tempfile.mkdtemp(prefix=f'{RUN_PREFIX}{os.getpid()}-',
                               dir=scratch)
    except OSError as e:
        return Configured(problem=(
            f'CMake could not be run ({e.strerror or e}: '
            f"'{e.filename or scratch}'); {FALLBACK}")), False
    started = time.monotonic()
    try:
        return _configure(cmake, package_path, scratch, run, cmake_files,
                          min(CONFIGURE_TIMEOUT_S, left))
    except OSError as e:  # the run directory cannot be written
        return Configured(problem=(
            f'CMake could not be run ({e.strerror or e}); {FALLBACK}')), \
            False
    finally:
        with _BUDGET_LOCK:
            _BUDGET_USED[workspace] = _BUDGET_USED.get(workspace, 0.0) + \
                time.monotonic() - started
        _remove_tree(run)


def _remove_abandoned_runs(scratch):
    """Remove run directories older than any configure can be.

    Left by a process that was killed; one of another process still
    configuring (on this machine or another sharing the build base) is
    younger than the time limit.
    """
    now = time.time()
    for name in os.listdir(scratch):
        path = os.path.join(scratch, name)
        try:
            abandoned = name.startswith(RUN_PREFIX) and \
                now - os.lstat(path).st_mtime > 2 * CONFIGURE_TIMEOUT_S
        except OSError:
            continue
        if abandoned:
            _remove_tree(path)


def _remove_tree(path):
    def writable_again(function, failed, _):
        # the package's CMake may have made a directory read-only
        try:
            os.chmod(os.path.dirname(failed), 0o700)
            os.chmod(failed, 0o700)
            function(failed)
        except OSError:
            pass
    shutil.rmtree(path, onerror=writable_again)


def _package_cmake_files(package_path):
    """{path relative to the package: bytes} of its CMake code.

    Every ``CMakeLists.txt`` and ``*.cmake`` of the package: what its
    configure may read, and so what its result depends on.
    """
    files = {}
    for root, dirs, names in os.walk(package_path):
        dirs[:] = sorted(d for d in dirs if not d.startswith('.') and
                         d not in _NOT_PACKAGE_CMAKE)
        for name in sorted(names):
            if name != 'CMakeLists.txt' and not name.endswith('.cmake'):
                continue
            path = os.path.join(root, name)
            try:
                content = safe_files.read_bytes(path, roots=[package_path])
            except OSError:
                continue  # CMake will say so, if the package needs it
            files[os.path.relpath(path, package_path)] = content
    return files


_OUR_CODE = []


def _content_key(cmake_files, version):
    digest = hashlib.sha1()
    if not _OUR_CODE:
        # a change to how we configure is a new key, like new content
        code = b''
        for path in (STAND_INS, __file__, sandbox.__file__,
                     sandbox.NO_EXEC):
            with open(path, 'rb') as h:
                code += h.read()
        _OUR_CODE.append(code)
    digest.update(_OUR_CODE[0])
    digest.update(f'{__version__} {version}'.encode())
    for relative, content in sorted(cmake_files.items()):
        digest.update(os.fsencode(relative) + b'\0')
        digest.update(hashlib.sha1(content).digest())
    return digest.hexdigest()


def _read_result(result_file, key):
    try:
        with open(result_file, encoding='utf-8') as h:
            return _result(json.load(h), key)
    except (OSError, ValueError):
        return None


def _result(data, key):
    try:
        if data['key'] != key:
            return None
        return Configured(
            executables=data['executables'],
            registrations=[tuple(r) for r in data['registrations']],
            problem=data['problem'])
    except (KeyError, TypeError):
        return None


_COMMENT = re.compile(r'#\[(=*)\[.*?\]\1\]|#[^\n]*', re.DOTALL)
# a command invocation starts its line (CMake's grammar); comments out
_COMMAND_CALL = re.compile(r'^[ \t]*([A-Za-z_]\w*)[ \t]*\(', re.MULTILINE)


def strip_comments(text):
    """CMake code without its line and bracket (``#[[ … ]]``) comments."""
    return _COMMENT.sub('', text)


def called_commands(cmake_files):
    """The names of the commands the CMake files call, lower case, sorted."""
    names = set()
    for content in cmake_files.values():
        text = strip_comments(content.decode('utf-8', 'replace'))
        names.update(m.group(1).lower() for m in _COMMAND_CALL.finditer(text))
    return sorted(names)


def _configure_environment():
    """The environment CMake runs in: none of the user's CMake settings.

    ``CMAKE_PREFIX_PATH``, ``CMAKE_GENERATOR``, ``CMAKE_TOOLCHAIN_FILE``
    and the like would make our configure depend on the shell it runs in.
    """
    environment = {'LC_ALL': 'C', 'LANG': 'C'}
    for name in ('PATH', 'HOME', 'TMPDIR'):
        if name in os.environ:
            environment[name] = os.environ[name]
    return environment


_VIEW = []
_VIEW_LOCK = threading.Lock()


def _cmake_view(binary):
    """What the cmake `binary` needs to run in the sandbox.

    :raises OSError: when a part cannot be found
    """
    with _VIEW_LOCK:
        if not _VIEW:
            _, (major, minor) = cmake_version()
            # CMake finds its modules from where its binary is, as here
            root = os.path.join(os.path.dirname(os.path.dirname(binary)),
                                'share', f'cmake-{major}.{minor}')
            if not os.path.isdir(os.path.join(root, 'Modules')):
                raise OSError(f"CMake's modules are not in '{root}'")
            _VIEW.append([binary, root, STAND_INS] +
                         sandbox.shared_libraries(binary))
        return _VIEW[0]


def _runner(binary, package_path, run, control):
    """(argv prefix running CMake, its environment, None) or a problem.

    In the sandbox; where none can be made, only when the user allows it,
    and then still unable to start a program.
    """
    try:
        view = _cmake_view(binary)
        problem = sandbox.sandbox_problem(binary, view, run)
    except OSError as e:
        problem = f'the sandbox cannot be assembled ({e})'
    if problem is None:
        return sandbox.sandboxed_command(
            [binary], read_only=view + [package_path], writable=run,
            read_only_inside=[control]), None, None
    if without_sandbox_allowed():
        environment = {'PATH': sandbox.PATH, 'HOME': run, 'LANG': 'C',
                       'LC_ALL': 'C'}
        return sandbox.no_exec_command([binary]), environment, None
    return None, None, (
        f"{problem}, so the package's CMake code is not run; {FALLBACK} "
        f'(set {CMAKE_WITHOUT_SANDBOX_ENVIRONMENT_VARIABLE.name}=1 to run it '
        'without a sandbox, for code you trust)')


def _configure(cmake, package_path, scratch, run, cmake_files, timeout):
    """(Configured, whether it may be kept) of configuring in `run`."""
    build_dir = os.path.join(run, 'build')
    control = os.path.join(run, 'control')
    # a client's query, as colcon-cmake's: the codemodel reader reads the
    # reply of any client
    query = os.path.join(
        build_dir, '.cmake', 'api', 'v1', 'query', 'client-colcon-rsia')
    os.makedirs(query)
    os.makedirs(control)
    with open(os.path.join(query, 'codemodel-v2'), 'w'):
        pass
    record_file = os.path.join(run, 'registrations.txt')
    with open(record_file, 'w'):
        pass
    top_level = os.path.join(control, 'rsia_top_level.cmake')
    with open(top_level, 'w', encoding='utf-8') as h:
        h.write(
            '# written by colcon-rsia: see ros_stand_ins.cmake\n'
            f'set(RSIA_RECORD_FILE {_cmake_quoted(record_file)})\n'
            'set(RSIA_UNKNOWN_COMMANDS '
            f'{" ".join(called_commands(cmake_files))})\n'
            f'include({_cmake_quoted(STAND_INS)})\n')
    binary = os.path.realpath(cmake)
    runner, environment, problem = _runner(binary, package_path, run,
                                           control)
    if problem is not None:
        return Configured(problem=problem), False
    command = runner + [
        '-S', package_path, '-B', build_dir, '-G', 'Unix Makefiles',
        f'-DCMAKE_PROJECT_TOP_LEVEL_INCLUDES={top_level}',
        # tests are not nodes
        '-DBUILD_TESTING=OFF', '-DCATKIN_ENABLE_TESTING=OFF',
        # nothing is downloaded
        '-DFETCHCONTENT_FULLY_DISCONNECTED=ON',
        '-Wno-dev', '--no-warn-unused-cli'] + _no_compiler_arguments(binary)
    process = subprocess.Popen(
        command, cwd=run, env=environment, stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        start_new_session=True)
    try:
        output, _ = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        # the sandbox and whatever it started
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        return Configured(problem=(
            f'CMake configure took longer than {timeout:g} s and '
            f'was stopped; {FALLBACK}')), False
    output = output.decode('utf-8', 'replace')
    try:
        safe_files.write_text_atomically(
            os.path.join(scratch, 'configure.log'), output)
    except OSError:
        pass
    executables = None
    if process.returncode == 0:
        executables = executables_from_codemodel(build_dir)
    if executables is None:
        problem = _not_started(process.returncode, output) or \
            f'CMake configure failed: {first_error(output)}'
        return Configured(problem=f'{problem}; {FALLBACK}'), \
            process.returncode > 0 and _error_in_cmake_code(output)
    return Configured(executables=executables,
                      registrations=_read_registrations(record_file)), True


def _no_compiler_arguments(binary):
    """CMake arguments that make it need (and run) no compiler.

    The compilers are taken as given (``CMAKE_<LANG>_COMPILER_FORCED``):
    nothing is compiled, no compiler needs to be installed, and none could
    start in the sandbox. CMake only checks that the named file exists.
    """
    arguments = [f'-DCMAKE_MAKE_PROGRAM={binary}']
    for language in ('C', 'CXX'):
        arguments += [
            f'-DCMAKE_{language}_COMPILER={binary}',
            f'-DCMAKE_{language}_COMPILER_FORCED=TRUE',
            f'-DCMAKE_{language}_COMPILER_ID_RUN=TRUE',
            f'-DCMAKE_{language}_COMPILER_ID={STAND_IN_COMPILER_ID}',
            f'-DCMAKE_{language}_COMPILER_VERSION={STAND_IN_COMPILER_VERSION}']
    return arguments


def _not_started(returncode, output):
    """Why CMake did not run to its end, when it is not CMake's error."""
    if returncode < 0:
        return f'CMake was stopped by signal {-returncode}'
    for line in output.splitlines():
        # bubblewrap's and no_exec.py's own messages
        if line.startswith(('bwrap: ', 'no_exec: ')):
            return f'CMake could not be started ({line[:300]})'
    return None


def _error_in_cmake_code(output):
    """Whether CMake failed on the CMake code (which a rerun repeats).

    ``CMake Error at CMakeLists.txt:4 (add_executable):`` names code;
    ``CMake Error: CMAKE_CXX_COMPILER not set`` and the like do not.
    """
    return re.search(r'^CMake Error (at|in) ', output, re.MULTILINE) \
        is not None


def _cmake_quoted(text):
    return '"' + re.sub(r'([\\"$])', r'\\\1', text) + '"'


def first_error(output):
    """The first error CMake printed, on one line."""
    lines = output.splitlines()
    for i, line in enumerate(lines):
        if line.startswith('CMake Error'):
            # 'CMake Error at CMakeLists.txt:4 (add_executable):' + message
            # and its indented message, up to a blank line
            place = re.sub(r'^CMake Error( at)?:?\s*', '', line.strip())
            message = []
            for following in lines[i + 1:]:
                if not following.strip():
                    if message:
                        break
                    continue
                if not following.startswith(' '):
                    break
                message.append(following.strip())
            text = place.rstrip(':') + (': ' + ' '.join(message)
                                        if message else '')
            return re.sub(r'\s+', ' ', text)[:300]
    return 'no codemodel was written'


def _read_registrations(record_file):
    registrations = []
    try:
        with open(record_file, encoding='utf-8', errors='replace') as h:
            for line in h:
                fields = line.rstrip('\n').split('\t')
                if fields[0] in ('node', 'nodes'):
                    registrations.append(tuple(fields))
    except OSError:
        pass
    return registrations
