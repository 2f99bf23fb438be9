# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The CMake code of an unbuilt package runs in a sandbox (issue 40, item 1).

Each way a package's CMake code could start a program (the six the probe
found, and more), write outside the build base, fetch or read what is not
the package's is a package here. Its program would print ``_ran`` (which
names the executable it makes) and touch a marker under the test's
directory: the executables CMake reports and the files under the test's
directory show whether anything ran or was written. Run without the
sandbox too (``COLCON_RSIA_CMAKE_WITHOUT_SANDBOX=1``), where a marker could
be written: nothing runs there either.
"""

import http.server
import os
import subprocess
import threading

from colcon_rsia.package import cmake_configure
from colcon_rsia.package import sandbox
from colcon_rsia.package.nodes import find_executables
import pytest
from test_cmake_configure import write_package

WITHOUT_SANDBOX = 'COLCON_RSIA_CMAKE_WITHOUT_SANDBOX'

# {case: CMake code run before the package's add_executable(node${said})}:
# each would set `said` to the program's output and touch the marker
PROGRAM_RUNS = {
    'before_project': (
        'execute_process(COMMAND {script} OUTPUT_VARIABLE said)\n'
        'project(eager)\n'),
    'underscore_command': (
        'project(eager)\n'
        '_execute_process(COMMAND {script} OUTPUT_VARIABLE said)\n'),
    'cmake_language_call': (
        'project(eager)\n'
        'cmake_language(CALL _execute_process COMMAND {script} '
        'OUTPUT_VARIABLE said)\n'),
    'list_file_in_cmake_root': (
        'project(eager)\n'
        'set(CMAKE_CURRENT_LIST_FILE "${{CMAKE_ROOT}}/Modules/x.cmake")\n'
        'execute_process(COMMAND {script} OUTPUT_VARIABLE said)\n'),
    'empty_cmake_root': (
        'project(eager)\n'
        'set(CMAKE_ROOT "")\n'
        'execute_process(COMMAND {script} OUTPUT_VARIABLE said)\n'),
    'no_top_level_includes': (
        'set(CMAKE_PROJECT_TOP_LEVEL_INCLUDES "")\n'
        'project(eager)\n'
        'execute_process(COMMAND {script} OUTPUT_VARIABLE said)\n'),
    'find_git_runs_git_executable': (
        'project(eager)\n'
        'set(GIT_EXECUTABLE {script})\n'
        'include(FindGit)\n'
        'set(said "${{GIT_VERSION_STRING}}")\n'),
    'exec_program': (
        'project(eager)\n'
        'exec_program({script} OUTPUT_VARIABLE said)\n'),
    'runtime_dependencies_tool': (
        'project(eager)\n'
        'set(CMAKE_GET_RUNTIME_DEPENDENCIES_PLATFORM linux+elf)\n'
        'set(CMAKE_GET_RUNTIME_DEPENDENCIES_TOOL objdump)\n'
        'set(CMAKE_GET_RUNTIME_DEPENDENCIES_COMMAND {script})\n'
        'file(GET_RUNTIME_DEPENDENCIES EXECUTABLES ${{CMAKE_COMMAND}}\n'
        '     RESOLVED_DEPENDENCIES_VAR said)\n'),
    'hostname_program': (
        'project(eager)\n'
        'set(HOSTNAME {script})\n'
        'site_name(said)\n'
        'if(said STREQUAL "localhost")\n'
        '  set(said "")\n'
        'endif()\n'),
}


def _eager_package(root, code, marker):
    """A package whose CMake `code` would run its script (or cmake -E)."""
    script = root / 'eager' / 'tools' / 'run.sh'
    package = write_package(root / 'eager', (
        'cmake_minimum_required(VERSION 3.8)\n' + code +
        'add_executable(node${said} src/node.cpp)\n'), sources=[
            'src/node.cpp'])
    script.parent.mkdir()
    script.write_text(f'#!/bin/sh\ntouch {marker}\nprintf _ran\n')
    script.chmod(0o755)
    return package, script


def _files_outside(root, build_base):
    """Every path under `root` but the build base."""
    found = set()
    for directory, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs
                   if os.path.join(directory, d) != str(build_base)]
        found.update(os.path.join(directory, n) for n in dirs + files)
    return found


def _configure(package, build_base):
    diagnostics = []
    executables = find_executables(
        package_path=str(package), build_base=str(build_base),
        diagnostics=diagnostics)
    return executables, diagnostics


@pytest.fixture(params=['sandbox', 'without_sandbox'])
def mode(request, monkeypatch):
    if request.param == 'without_sandbox':
        # where no sandbox can be made and the user allows CMake anyway,
        # no program starts either (but files can be written)
        monkeypatch.setattr(sandbox, 'bwrap_executable', lambda: None)
        monkeypatch.setattr(sandbox, '_PROBED', {})
        monkeypatch.setenv(WITHOUT_SANDBOX, '1')
    return request.param


@pytest.mark.parametrize('case', sorted(PROGRAM_RUNS))
@pytest.mark.parametrize('program', ['script', 'cmake'])
def test_no_program_of_the_package_runs(tmp_path, case, program, mode):
    marker = tmp_path / 'ran'
    code = PROGRAM_RUNS[case]
    if program == 'cmake':
        # CMake itself is in the sandbox: it must not start either
        code = code.replace(
            '{script}', '${{CMAKE_COMMAND}} -E echo_append _ran')
        if case == 'find_git_runs_git_executable':
            pytest.skip('FindGit gives its git executable no arguments')
    package, script = _eager_package(tmp_path, code.format(
        script=tmp_path / 'eager' / 'tools' / 'run.sh'), marker)
    build_base = tmp_path / 'build'
    before = _files_outside(tmp_path, build_base)
    executables, diagnostics = _configure(package, build_base)
    assert not marker.exists()
    assert _files_outside(tmp_path, build_base) == before
    if case == 'runtime_dependencies_tool':
        # file() is not replaced: its program fails to start, and the
        # configure with it
        assert len(diagnostics) == 1, diagnostics
        assert 'Failed to start objdump process' in diagnostics[0]
        return
    assert executables == {'node': [str(package / 'src' / 'node.cpp')]}, \
        diagnostics
    assert diagnostics == []


WRITES = {
    'file_write': 'file(WRITE {target} "x")\n',
    'file_append': 'file(APPEND {target} "x")\n',
    'file_generate': 'file(GENERATE OUTPUT {target} CONTENT "x")\n',
    'configure_file': 'configure_file(CMakeLists.txt {target} COPYONLY)\n',
    'file_copy': 'file(COPY CMakeLists.txt DESTINATION {directory})\n',
    'file_make_directory': 'file(MAKE_DIRECTORY {directory}/made)\n',
    'file_touch': 'file(TOUCH {target})\n',
}


@pytest.mark.parametrize('case', sorted(WRITES))
def test_nothing_is_written_outside_the_build_base(tmp_path, case):
    outside = tmp_path / 'outside'
    outside.mkdir()
    target = outside / 'written.txt'
    package = write_package(tmp_path / 'writer', (
        'cmake_minimum_required(VERSION 3.8)\n'
        'project(writer)\n'
        + WRITES[case].format(target=target, directory=outside) +
        'add_executable(node src/node.cpp)\n'), sources=['src/node.cpp'])
    build_base = tmp_path / 'build'
    before = _files_outside(tmp_path, build_base)
    _configure(package, build_base)
    assert not target.exists()
    assert _files_outside(tmp_path, build_base) == before


class _Recorder(http.server.BaseHTTPRequestHandler):
    requests = []

    def do_GET(self):  # noqa: N802
        self.requests.append(self.path)
        self.send_response(200)
        self.end_headers()
        self.wfile.write(b'fetched')

    def log_message(self, *args):
        pass


@pytest.fixture
def web_server():
    _Recorder.requests = []
    server = http.server.HTTPServer(('127.0.0.1', 0), _Recorder)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f'http://127.0.0.1:{server.server_address[1]}', _Recorder.requests
    server.shutdown()
    server.server_close()


def test_nothing_is_fetched(tmp_path, web_server):
    url, requests = web_server
    package = write_package(tmp_path / 'fetcher', (
        'cmake_minimum_required(VERSION 3.8)\n'
        'project(fetcher)\n'
        f'file(DOWNLOAD {url}/payload ${{CMAKE_BINARY_DIR}}/payload\n'
        '     TIMEOUT 5 STATUS status)\n'
        f'file(DOWNLOAD {url}/out {tmp_path}/downloaded TIMEOUT 5)\n'
        'file(READ ${CMAKE_BINARY_DIR}/payload said)\n'
        'add_executable(node${said} src/node.cpp)\n'),
        sources=['src/node.cpp'])
    executables, diagnostics = _configure(package, tmp_path / 'build')
    assert requests == []
    assert not (tmp_path / 'downloaded').exists()
    assert executables == {'node': [str(package / 'src' / 'node.cpp')]}


def test_nothing_of_the_user_is_seen(tmp_path, monkeypatch):
    # a secret beside the package, in the environment, in the home
    (tmp_path / 'secret.txt').write_text('_secret')
    monkeypatch.setenv('RSIA_TEST_TOKEN', '_token')
    package = write_package(tmp_path / 'reader', (
        'cmake_minimum_required(VERSION 3.8)\n'
        'project(reader)\n'
        f'if(EXISTS {tmp_path}/secret.txt)\n'
        f'  file(READ {tmp_path}/secret.txt secret)\n'
        'endif()\n'
        'if(EXISTS /etc/passwd OR EXISTS $ENV{HOME}/.bashrc)\n'
        '  set(secret "${secret}_system")\n'
        'endif()\n'
        'add_executable(node${secret}$ENV{RSIA_TEST_TOKEN} src/node.cpp)\n'
        'message(FATAL_ERROR "${secret}$ENV{RSIA_TEST_TOKEN}")\n'),
        sources=['src/node.cpp'])
    executables, diagnostics = _configure(package, tmp_path / 'build')
    # the message carried nothing out either
    assert diagnostics == [
        'CMake configure failed: CMakeLists.txt:10 (message); CMakeLists.txt '
        'read by the fallback reader']
    log = (tmp_path / 'build' / 'rsia' / 'cmake_configure' /
           'configure.log').read_text()
    assert '_secret' not in log and '_token' not in log and '_system' not in log


def test_without_a_sandbox_cmake_is_not_run_unless_allowed(
        tmp_path, monkeypatch):
    monkeypatch.setattr(sandbox, 'bwrap_executable', lambda: None)
    monkeypatch.setattr(sandbox, '_PROBED', {})
    monkeypatch.delenv(WITHOUT_SANDBOX, raising=False)
    # a loop the fallback reader cannot follow tells who read the package
    package = write_package(tmp_path / 'looped', (
        'cmake_minimum_required(VERSION 3.8)\n'
        'project(looped)\n'
        'foreach(name alpha beta)\n'
        '  add_executable(${name}_node src/${name}.cpp)\n'
        'endforeach()\n'
        'add_executable(plain src/alpha.cpp)\n'),
        sources=['src/alpha.cpp', 'src/beta.cpp'])
    executables, diagnostics = _configure(package, tmp_path / 'build')
    assert executables == {'plain': [str(package / 'src' / 'alpha.cpp')]}
    assert diagnostics == [
        "bubblewrap (bwrap) is not installed, so the package's CMake code "
        'is not run; CMakeLists.txt read by the fallback reader (set '
        'COLCON_RSIA_CMAKE_WITHOUT_SANDBOX=1 to run it without a sandbox, '
        'for code you trust)']
    assert not (tmp_path / 'build' / 'rsia' / 'cmake_configure' /
                'result.json').exists()
    # allowed: CMake runs (and the next run asks again)
    monkeypatch.setenv(WITHOUT_SANDBOX, '1')
    monkeypatch.setattr(cmake_configure, '_NOT_KEPT', {})
    executables, diagnostics = _configure(package, tmp_path / 'build')
    assert sorted(executables) == ['alpha_node', 'beta_node', 'plain']
    assert diagnostics == []


SANDBOXED_PROBE = r"""
import json, os, socket, sys
facts = {'environment': sorted(os.environ), 'etc': os.listdir('/etc'),
         'home': os.path.exists(sys.argv[3])}
status = open('/proc/self/status').read()
facts['capabilities'] = [l.split()[1] for l in status.splitlines()
                         if l.startswith('CapEff')]
facts['wrote'] = []
for path in ('/written', sys.executable):
    try:
        open(path, 'a')
        facts['wrote'].append(path)
    except OSError:
        pass
try:
    socket.create_connection(('127.0.0.1', int(sys.argv[2])), timeout=5)
    facts['connected'] = True
except OSError:
    facts['connected'] = False
try:
    os.execv('/bin/true', ['true'])
except OSError as e:
    facts['exec'] = e.strerror
print(json.dumps(facts))
"""


def test_the_sandbox_itself(tmp_path, web_server):
    import json
    url = web_server[0]
    writable = tmp_path / 'scratch'
    writable.mkdir()
    python = sandbox.interpreter()
    command = sandbox.sandboxed_command(
        [python, '-I', '-S', '-c', SANDBOXED_PROBE,
         str(tmp_path / 'outside.txt'), url.rsplit(':', 1)[1],
         os.path.expanduser('~/.profile')],
        read_only=[python], writable=str(writable))
    result = subprocess.run(command, capture_output=True, text=True,
                            timeout=60)
    facts = json.loads(result.stdout)
    # (bubblewrap sets PWD to the working directory)
    assert facts['environment'] == ['HOME', 'LANG', 'LC_ALL', 'PATH', 'PWD']
    assert facts['capabilities'] == ['0000000000000000']
    assert facts['wrote'] == []
    assert facts['connected'] is False
    assert facts['exec'] == 'Operation not permitted'
    assert not (tmp_path / 'outside.txt').exists()
    # none of the user's files, none of /etc but the loader's cache
    assert facts['home'] is False
    assert facts['etc'] == ['ld.so.cache']


def test_a_package_of_old_cmake_policies_configures(tmp_path, mode):
    # most ROS 1 packages say cmake_minimum_required(VERSION 2.8.3): the
    # replacements run under those policies too (if(IN_LIST) was an error
    # there, and every catkin package's configure failed)
    package = write_package(tmp_path / 'old', (
        'cmake_minimum_required(VERSION 2.8.3)\n'
        'project(old)\n'
        'execute_process(COMMAND nothing OUTPUT_VARIABLE said\n'
        '                RESULT_VARIABLE result)\n'
        'if(NOT result EQUAL 0)\n'
        '  message(FATAL_ERROR "the replacement reports success")\n'
        'endif()\n'
        'add_executable(old_node src/node.cpp)\n'), sources=['src/node.cpp'])
    executables, diagnostics = _configure(package, tmp_path / 'build')
    assert executables == {'old_node': [str(package / 'src' / 'node.cpp')]}, \
        diagnostics
    assert diagnostics == []
