# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Unbuilt packages are configured by CMake itself, with ROS stood in for.

The expected executables are written from reading each CMakeLists.txt; the
built test workspaces check that our configure finds what the build's own
codemodel says.
"""

import json
import os
from pathlib import Path
import subprocess
import sys
import time

from colcon_rsia.package import cmake_configure
from colcon_rsia.package.nodes import find_components
from colcon_rsia.package.nodes import find_executables
import pytest

IDIOMS = """
cmake_minimum_required(VERSION 3.8)
project(idioms)
find_package(ament_cmake REQUIRED)
find_package(ament_cmake_auto REQUIRED)
find_package(rclcpp REQUIRED)
find_package(Boost REQUIRED COMPONENTS system thread)
ament_auto_find_build_dependencies()
include(cmake/tools.cmake)

# one executable per node, made by a macro in a loop
macro(idioms_node name)
  add_executable(${name}_node src/${name}.cpp)
  ament_target_dependencies(${name}_node rclcpp)
endmacro()
foreach(node talker listener)
  idioms_node(${node})
endforeach()

# a source list of several values; imported targets that are not installed
set(FUSION_SRCS src/fusion_main.cpp
  src/fusion_math.cpp)
add_executable(fusion ${FUSION_SRCS})
target_link_libraries(fusion rclcpp::rclcpp Boost::system ${Boost_LIBRARIES})
add_dependencies(fusion ${PROJECT_NAME}_generate_messages_cpp)

# a list grown with list(APPEND), installed under another name
set(MAPPER_SRCS src/mapper_main.cpp)
list(APPEND MAPPER_SRCS src/mapper_grid.cpp)
add_executable(mapper ${MAPPER_SRCS})
set_target_properties(mapper PROPERTIES OUTPUT_NAME grid_mapper)

ament_auto_add_executable(auto_node src/auto_node.cpp)
ament_auto_add_library(filters SHARED src/filters.cpp)

# add_executable(retired src/retired.cpp)

add_library(camera SHARED src/camera.cpp)
rclcpp_components_register_node(camera
  PLUGIN "idioms::Camera" EXECUTABLE camera_node)
vendor_specific_setup(camera FAST)  # defined by no package here

# a library that is not installed, a target made by a command nothing
# defines, a version of a package found through another
find_library(GEO_LIB NAMES surely_not_installed_geo REQUIRED)
target_link_libraries(fusion ${GEO_LIB})
pybind11_add_module(py_ext src/py_ext.cpp)
target_link_libraries(py_ext rclcpp::rclcpp)
rosidl_generate_interfaces(${PROJECT_NAME} msg/Fused.msg)
if(${rosidl_cmake_VERSION} VERSION_LESS 2.5.0)
  rosidl_target_interfaces(fusion ${PROJECT_NAME} rosidl_typesupport_cpp)
else()
  rosidl_get_typesupport_target(fused_target ${PROJECT_NAME}
    rosidl_typesupport_cpp)
  target_link_libraries(fusion ${fused_target})
endif()

if(BUILD_TESTING)
  find_package(ament_cmake_gtest REQUIRED)
  ament_add_gtest(test_fusion test/test_fusion.cpp)
  add_executable(fusion_check test/fusion_check.cpp)
endif()

install(TARGETS fusion mapper talker_node listener_node
  DESTINATION lib/${PROJECT_NAME})
ament_auto_package()
"""

TOOLS = """
function(idioms_tool name)
  add_executable(${name} tools/${name}.cpp)
endfunction()
idioms_tool(inspector)
"""

SOURCES = [
    'src/talker.cpp', 'src/listener.cpp', 'src/fusion_main.cpp',
    'src/fusion_math.cpp', 'src/mapper_main.cpp', 'src/mapper_grid.cpp',
    'src/auto_node.cpp', 'src/filters.cpp', 'src/retired.cpp',
    'src/camera.cpp', 'test/test_fusion.cpp', 'test/fusion_check.cpp',
    'tools/inspector.cpp', 'src/py_ext.cpp']


def write_package(root, cmakelists, sources=SOURCES, extra=None):
    root.mkdir(parents=True, exist_ok=True)
    (root / 'CMakeLists.txt').write_text(cmakelists)
    for relative in sources:
        (root / relative).parent.mkdir(parents=True, exist_ok=True)
        (root / relative).write_text('int main() { return 0; }\n')
    for relative, text in (extra or {}).items():
        (root / relative).parent.mkdir(parents=True, exist_ok=True)
        (root / relative).write_text(text)
    return root


@pytest.fixture
def idioms(tmp_path):
    return write_package(tmp_path / 'idioms', IDIOMS,
                         extra={'cmake/tools.cmake': TOOLS})


def test_common_cmake_idioms_are_read_by_cmake(idioms, tmp_path):
    diagnostics = []
    executables = find_executables(
        package_path=str(idioms), build_base=str(tmp_path / 'build'),
        diagnostics=diagnostics)
    assert diagnostics == []

    def paths(*relative):
        return [str(idioms / r) for r in relative]
    # not: the commented-out 'retired', the tests (testing is off: tests
    # are not nodes), the libraries
    assert executables == {
        'talker_node': paths('src/talker.cpp'),
        'listener_node': paths('src/listener.cpp'),
        'fusion': paths('src/fusion_main.cpp', 'src/fusion_math.cpp'),
        'grid_mapper': paths('src/mapper_main.cpp', 'src/mapper_grid.cpp'),
        'auto_node': paths('src/auto_node.cpp'),
        'inspector': paths('tools/inspector.cpp'),
    }
    components = find_components(
        package_path=str(idioms), exported_classes=[],
        build_base=str(tmp_path / 'build'))
    assert components == {'camera_node': 'idioms::Camera'}


def test_components_registered_by_a_macro_are_recorded(tmp_path):
    package = write_package(tmp_path / 'cams', """
cmake_minimum_required(VERSION 3.8)
project(cams)
find_package(rclcpp_components REQUIRED)
add_library(cams SHARED src/cams.cpp)
macro(register_camera name)
  rclcpp_components_register_node(cams
    PLUGIN "cams::${name}" EXECUTABLE ${name}_node)
endmacro()
register_camera(Front)
register_camera(Rear)
rclcpp_components_register_nodes(cams "cams::Talker" "other::Talker")
""", sources=['src/cams.cpp'])
    components = find_components(
        package_path=str(package), exported_classes=[],
        build_base=str(tmp_path / 'build'))
    # the two Talkers keep their namespaces to tell them apart
    assert components == {
        'Front_node': 'cams::Front', 'Rear_node': 'cams::Rear',
        'cams::Talker': 'cams::Talker', 'other::Talker': 'other::Talker'}


BROKEN = """cmake_minimum_required(VERSION 3.8)
project(broken)
add_executable(first src/first.cpp)
add_executable(second src/second.cpp
"""


def test_a_configure_that_fails_falls_back_with_one_diagnostic(tmp_path):
    package = write_package(tmp_path / 'broken', BROKEN,
                            sources=['src/first.cpp', 'src/second.cpp'])
    diagnostics = []
    executables = find_executables(
        package_path=str(package), build_base=str(tmp_path / 'build'),
        diagnostics=diagnostics)
    # the fallback reader finds the complete add_executable only
    assert executables == {'first': [str(package / 'src' / 'first.cpp')]}
    assert len(diagnostics) == 1
    assert diagnostics[0].startswith(
        'CMake configure failed: CMakeLists.txt:4: Parse error')
    assert diagnostics[0].endswith(
        '; CMakeLists.txt read by the fallback reader')


def test_an_old_cmake_is_not_asked(idioms, tmp_path, monkeypatch):
    monkeypatch.setattr(cmake_configure, '_CMAKE_VERSION',
                        [('/usr/bin/cmake', (3, 22))])
    diagnostics = []
    executables = find_executables(
        package_path=str(idioms), build_base=str(tmp_path / 'build'),
        diagnostics=diagnostics)
    assert diagnostics == [
        'CMake 3.22 is older than 3.24, which CMake needs to stand in for '
        'find_package(); CMakeLists.txt read by the fallback reader']
    # what the fallback reader makes of it: no loop, no multi-value set(),
    # no list(APPEND), no OUTPUT_NAME, no include(), no if()
    assert executables == {
        'mapper': [str(idioms / 'src' / 'mapper_main.cpp')],
        'auto_node': [str(idioms / 'src' / 'auto_node.cpp')],
        'fusion_check': [str(idioms / 'test' / 'fusion_check.cpp')],
    }
    assert not (tmp_path / 'build' / 'rsia').exists()


def test_a_configure_that_hangs_is_stopped(tmp_path, monkeypatch):
    monkeypatch.setattr(cmake_configure, 'CONFIGURE_TIMEOUT_S', 2)
    package = write_package(tmp_path / 'slow', """
cmake_minimum_required(VERSION 3.8)
project(slow)
while(TRUE)
endwhile()
add_executable(slow src/slow.cpp)
""", sources=['src/slow.cpp'])
    diagnostics = []
    executables = find_executables(
        package_path=str(package), build_base=str(tmp_path / 'build'),
        diagnostics=diagnostics)
    assert executables == {'slow': [str(package / 'src' / 'slow.cpp')]}
    assert diagnostics == [
        'CMake configure took longer than 2 s and was stopped; '
        'CMakeLists.txt read by the fallback reader']


def test_an_unchanged_package_is_configured_once(idioms, tmp_path,
                                                 monkeypatch):
    build = str(tmp_path / 'build')
    first = find_executables(package_path=str(idioms), build_base=build)
    runs = []
    real_configure = cmake_configure._configure
    monkeypatch.setattr(cmake_configure, '_configure',
                        lambda *a: runs.append(a) or real_configure(*a))
    assert find_executables(package_path=str(idioms), build_base=build) == \
        first
    assert runs == []
    # a change to an included .cmake file is a change of the package
    (idioms / 'cmake' / 'tools.cmake').write_text(
        TOOLS + 'idioms_tool(probe)\n')
    (idioms / 'tools' / 'probe.cpp').write_text('int main() {}\n')
    again = find_executables(package_path=str(idioms), build_base=build)
    assert len(runs) == 1
    assert again == dict(first, probe=[str(idioms / 'tools' / 'probe.cpp')])


def test_configure_does_not_use_the_users_cmake_environment(
        tmp_path, monkeypatch):
    # a generator that does not exist would fail every configure
    monkeypatch.setenv('CMAKE_GENERATOR', 'No Such Generator')
    monkeypatch.setenv('CMAKE_PREFIX_PATH', str(tmp_path / 'nowhere'))
    package = write_package(tmp_path / 'plain', """
cmake_minimum_required(VERSION 3.8)
project(plain)
add_executable(plain src/plain.cpp)
""", sources=['src/plain.cpp'])
    diagnostics = []
    assert find_executables(
        package_path=str(package), build_base=str(tmp_path / 'build'),
        diagnostics=diagnostics) == {
            'plain': [str(package / 'src' / 'plain.cpp')]}
    assert diagnostics == []


def _built_and_configured(workspace, tmp_path):
    packages = sorted(p.name for p in workspace.src.iterdir()
                      if (p / 'CMakeLists.txt').exists())
    assert packages
    for package in packages:
        path = str(workspace.src / package)
        built = find_executables(
            package_path=path, build_base=str(workspace.build_base / package))
        assert os.path.isdir(
            workspace.build_base / package / '.cmake' / 'api' / 'v1' /
            'reply'), package
        diagnostics = []
        configured = find_executables(
            package_path=path, build_base=str(Path(tmp_path) / package),
            diagnostics=diagnostics)
        yield package, built, configured, diagnostics


def test_configure_finds_what_the_build_finds_ros1(ros1_workspace, tmp_path):
    for package, built, configured, diagnostics in _built_and_configured(
            ros1_workspace, tmp_path):
        assert diagnostics == [], package
        assert configured == built, package


def test_configure_finds_what_the_build_finds_system(system_workspace,
                                                     tmp_path):
    for package, built, configured, diagnostics in _built_and_configured(
            system_workspace, tmp_path):
        assert diagnostics == [], package
        assert configured == built, package


def test_no_program_of_the_package_runs(tmp_path):
    # a configure reads targets: the package's execute_process() and
    # try_run() must not run anything on the analysing machine
    marker = tmp_path / 'ran'
    package = write_package(tmp_path / 'eager', f"""
cmake_minimum_required(VERSION 3.8)
project(eager)
execute_process(COMMAND touch {marker} RESULT_VARIABLE touched
                OUTPUT_VARIABLE said)
if(NOT touched EQUAL 0)
  message(FATAL_ERROR "the package stops when its command fails")
endif()
add_executable(eager_node src/eager_node.cpp)
""", sources=['src/eager_node.cpp'])
    diagnostics = []
    executables = find_executables(
        package_path=str(package), build_base=str(tmp_path / 'build'),
        diagnostics=diagnostics)
    assert not marker.exists()
    assert diagnostics == []
    assert executables == {
        'eager_node': [str(package / 'src' / 'eager_node.cpp')]}


# --- issue 40, item 3: configures at once, results that may not repeat -------

SLOW = """cmake_minimum_required(VERSION 3.8)
project(slow)
add_executable(slow_node src/slow.cpp)
# a second or two of CMake's time
foreach(i RANGE {count})
  math(EXPR twice "${{i}} * 2")
endforeach()
"""
CONFIGURE_ONE = """
import json, sys
from colcon_rsia.package.nodes import find_executables
diagnostics = []
executables = find_executables(package_path=sys.argv[1],
                               build_base=sys.argv[2], diagnostics=diagnostics)
print(json.dumps([executables, diagnostics]))
"""


def test_two_analyses_configuring_one_package_at_once(tmp_path):
    package = write_package(tmp_path / 'slow', SLOW.format(count=300000),
                            sources=['src/slow.cpp'])
    build = str(tmp_path / 'build')
    command = [sys.executable, '-c', CONFIGURE_ONE, str(package), build]
    first = subprocess.Popen(command, stdout=subprocess.PIPE, text=True)
    # the second starts while the first configures
    time.sleep(0.5)
    second = subprocess.Popen(command, stdout=subprocess.PIPE, text=True)
    expected = [{'slow_node': [str(package / 'src' / 'slow.cpp')]}, []]
    assert json.loads(first.communicate(timeout=300)[0]) == expected
    assert json.loads(second.communicate(timeout=300)[0]) == expected
    # and what they kept is right
    assert json.loads(subprocess.run(
        command, stdout=subprocess.PIPE, text=True, timeout=300,
        check=True).stdout) == expected


def test_a_configure_that_timed_out_is_tried_again_next_run(
        tmp_path, monkeypatch):
    # a configure that ran out of time under load is not the package's
    # answer: the next run (here: a fresh memory of this one) asks again
    package = write_package(tmp_path / 'slow', SLOW.format(count=300000),
                            sources=['src/slow.cpp'])
    monkeypatch.setattr(cmake_configure, 'CONFIGURE_TIMEOUT_S', 0.2)
    diagnostics = []
    find_executables(package_path=str(package),
                     build_base=str(tmp_path / 'build'),
                     diagnostics=diagnostics)
    assert diagnostics == [
        'CMake configure took longer than 0.2 s and was stopped; '
        'CMakeLists.txt read by the fallback reader']
    monkeypatch.setattr(cmake_configure, 'CONFIGURE_TIMEOUT_S', 60)
    monkeypatch.setattr(cmake_configure, '_NOT_KEPT', {}, raising=False)
    diagnostics = []
    assert find_executables(
        package_path=str(package), build_base=str(tmp_path / 'build'),
        diagnostics=diagnostics) == {
            'slow_node': [str(package / 'src' / 'slow.cpp')]}
    assert diagnostics == []


def test_hanging_packages_share_one_time_budget(tmp_path, monkeypatch):
    # every package of a pull request looping forever costs the budget of
    # one run, not a time-out each
    monkeypatch.setattr(cmake_configure, 'CONFIGURE_TIMEOUT_S', 2)
    monkeypatch.setattr(cmake_configure, 'CONFIGURE_BUDGET_S', 3,
                        raising=False)
    said = []
    started = time.monotonic()
    for name in ('one', 'two', 'three', 'four'):
        package = write_package(tmp_path / 'src' / name, f"""
cmake_minimum_required(VERSION 3.8)
project({name})
while(TRUE)
endwhile()
""", sources=[])
        diagnostics = []
        find_executables(package_path=str(package),
                         build_base=str(tmp_path / 'build' / name),
                         diagnostics=diagnostics)
        said += diagnostics
    # two time-outs, not four
    assert time.monotonic() - started < 7
    assert said[0] == ('CMake configure took longer than 2 s and was '
                       'stopped; CMakeLists.txt read by the fallback reader')
    assert said[-1] == (
        'the CMake configures of this run took 3 s together, all the time '
        'they have; CMakeLists.txt read by the fallback reader')


def test_the_package_time_includes_its_configure(tmp_path, monkeypatch):
    # issue 40, item 15: a configure that took long showed "in 0.5s"
    from colcon_rsia.package import nodes
    from colcon_rsia.package import runner
    from helpers import GOOD_NODE
    package = write_package(tmp_path / 'timed', """
cmake_minimum_required(VERSION 3.8)
project(timed)
add_executable(timed_node src/timed.cpp)
""", sources=[])
    (package / 'src').mkdir()
    (package / 'src' / 'timed.cpp').write_text(GOOD_NODE)
    real_configure = nodes.configure_package
    calls = []

    def slow_first_configure(*args):
        if not calls:
            time.sleep(3)  # as a slow CMake would
        calls.append(args)
        return real_configure(*args)
    monkeypatch.setattr(nodes, 'configure_package', slow_first_configure)
    started = time.monotonic()
    outcome = runner.analyze(
        name='timed', package_type='ros.ament_cmake', path=str(package),
        build_base=str(tmp_path / 'build'), jobs=1, header_mode='model',
        workspace_package_dirs=[str(package)], without_build=True)
    took = time.monotonic() - started
    assert [n.id for n in outcome.summary.nodes] == ['timed/timed_node']
    # the whole of it (some of a second goes to calls and writes)
    assert outcome.summary.seconds > took - 1
    written = json.loads(
        (tmp_path / 'build' / 'rsia' / 'summary.json').read_text())
    assert written['seconds'] == outcome.summary.seconds
