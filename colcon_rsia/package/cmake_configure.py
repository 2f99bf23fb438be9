# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Which executables a CMake package makes, as CMake itself says.

A built package has CMake's file-API codemodel in its build directory
(colcon-cmake asks for it). An unbuilt one is configured here by the real
``cmake``, in ``<build base>/rsia/cmake_configure``, with
``ros_stand_ins.cmake`` standing in for ROS (which need not be installed):
every ``find_package`` succeeds with nothing in it, and the commands ROS
packages bring do nothing, except those that make targets or register
components. Only CMake's configure runs (what a build would run anyway),
with a time limit; its result is kept, keyed by the package's CMake files,
so an unchanged package is configured once.

When CMake cannot be asked (no ``cmake``, one older than 3.24, a configure
that fails), :func:`configure_package` says why in one sentence and the
caller reads ``CMakeLists.txt`` itself.
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
import threading
from typing import Optional

from colcon_rsia import __version__
from colcon_rsia import safe_files
from colcon_rsia.package import store

# the dependency provider (cmake_language(SET_DEPENDENCY_PROVIDER)) came
# with CMake 3.24
MINIMUM_CMAKE_VERSION = (3, 24)
CONFIGURE_TIMEOUT_S = 60
SCRATCH_DIRNAME = 'cmake_configure'
RESULT_FILENAME = 'result.json'
STAND_INS = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                         'ros_stand_ins.cmake')
FALLBACK = 'CMakeLists.txt read by the fallback reader'
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
    try:
        configured = _configure(cmake, package_path, scratch, cmake_files)
    except OSError as e:  # the scratch directory cannot be written
        return Configured(problem=f'CMake could not be run ({e}); {FALLBACK}')
    try:
        store.write_json_atomically(result_file, {
            'key': key, 'executables': configured.executables,
            'registrations': configured.registrations,
            'problem': configured.problem})
    except OSError:
        pass  # a result that cannot be kept only costs time
    return configured


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
        with open(STAND_INS, 'rb') as h, open(__file__, 'rb') as g:
            _OUR_CODE.append(h.read() + g.read())
    digest.update(_OUR_CODE[0])
    digest.update(f'{__version__} {version}'.encode())
    for relative, content in sorted(cmake_files.items()):
        digest.update(os.fsencode(relative) + b'\0')
        digest.update(hashlib.sha1(content).digest())
    return digest.hexdigest()


def _read_result(result_file, key):
    try:
        with open(result_file, encoding='utf-8') as h:
            data = json.load(h)
        if data['key'] != key:
            return None
        return Configured(
            executables=data['executables'],
            registrations=[tuple(r) for r in data['registrations']],
            problem=data['problem'])
    except (OSError, ValueError, KeyError, TypeError):
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


def _configure(cmake, package_path, scratch, cmake_files):
    build_dir = os.path.join(scratch, 'build')
    shutil.rmtree(build_dir, ignore_errors=True)
    # a client's query, as colcon-cmake's: the codemodel reader reads the
    # reply of any client
    query = os.path.join(
        build_dir, '.cmake', 'api', 'v1', 'query', 'client-colcon-rsia')
    os.makedirs(query, exist_ok=True)
    with open(os.path.join(query, 'codemodel-v2'), 'w'):
        pass
    record_file = os.path.join(scratch, 'registrations.txt')
    with open(record_file, 'w'):
        pass
    top_level = os.path.join(scratch, 'rsia_top_level.cmake')
    with open(top_level, 'w', encoding='utf-8') as h:
        h.write(
            '# written by colcon-rsia: see ros_stand_ins.cmake\n'
            f'set(RSIA_RECORD_FILE {_cmake_quoted(record_file)})\n'
            'set(RSIA_UNKNOWN_COMMANDS '
            f'{" ".join(called_commands(cmake_files))})\n'
            f'include({_cmake_quoted(STAND_INS)})\n')
    command = [
        cmake, '-S', package_path, '-B', build_dir,
        '-G', 'Unix Makefiles',
        f'-DCMAKE_PROJECT_TOP_LEVEL_INCLUDES={top_level}',
        # no compiler is run to check that it works: nothing is compiled
        '-DCMAKE_C_COMPILER_WORKS=1', '-DCMAKE_CXX_COMPILER_WORKS=1',
        # tests are not nodes
        '-DBUILD_TESTING=OFF', '-DCATKIN_ENABLE_TESTING=OFF',
        # nothing is downloaded
        '-DFETCHCONTENT_FULLY_DISCONNECTED=ON',
        '-Wno-dev', '--no-warn-unused-cli']
    process = subprocess.Popen(
        command, cwd=scratch, env=_configure_environment(),
        stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT, start_new_session=True)
    try:
        output, _ = process.communicate(timeout=CONFIGURE_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        # CMake and whatever it started
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        return Configured(problem=(
            f'CMake configure took longer than {CONFIGURE_TIMEOUT_S} s and '
            f'was stopped; {FALLBACK}'))
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
        return Configured(problem=(
            f'CMake configure failed: {first_error(output)}; {FALLBACK}'))
    registrations = _read_registrations(record_file)
    # the result is kept; what CMake wrote to get it is not needed
    shutil.rmtree(build_dir, ignore_errors=True)
    return Configured(executables=executables, registrations=registrations)


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
