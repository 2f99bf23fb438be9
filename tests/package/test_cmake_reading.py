# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Which executables and components a package's CMakeLists.txt makes.

Without a build, CMake configures the package (tests/package/test_cmake_configure.py);
when it cannot, the file itself is read, with the helper functions and macros
packages wrap add_executable in.
"""

import json

from colcon_rsia.package import cmake_configure
from colcon_rsia.package.nodes import find_components
from colcon_rsia.package.nodes import find_executables
from conftest import run_colcon

CMAKELISTS = """
cmake_minimum_required(VERSION 3.8)
project(demo)
set(TOOL_SOURCE src/tool.cpp)
# upstream demo_nodes_cpp style
function(custom_executable subfolder target)
  add_executable(${target} src/${subfolder}/${target}.cpp)
endfunction()
macro(register_camera name)
  rclcpp_components_register_node(demo_lib
    PLUGIN "demo::${name}" EXECUTABLE ${name}_node)
endmacro()
custom_executable(topics talker)
custom_executable(services server)
add_executable(${PROJECT_NAME}_tool ${TOOL_SOURCE})
register_camera(Camera)
rclcpp_components_register_node(demo_lib PLUGIN "${plugin}" EXECUTABLE ${exe})
"""


def test_helper_functions_macros_and_variables_are_expanded(
        tmp_path, monkeypatch):
    # the fallback reader: no cmake to ask
    monkeypatch.setattr(cmake_configure, '_CMAKE_VERSION', [(None, None)])
    (tmp_path / 'CMakeLists.txt').write_text(CMAKELISTS)
    diagnostics = []
    executables = find_executables(
        package_path=str(tmp_path), build_base=str(tmp_path / 'no_build'),
        diagnostics=diagnostics)
    assert diagnostics == [
        'cmake was not found; CMakeLists.txt read by the fallback reader']
    assert executables == {
        'talker': [str(tmp_path / 'src' / 'topics' / 'talker.cpp')],
        'server': [str(tmp_path / 'src' / 'services' / 'server.cpp')],
        'demo_tool': [str(tmp_path / 'src' / 'tool.cpp')],
    }
    components = find_components(
        package_path=str(tmp_path),
        exported_classes=[('a::Talker', 'rclcpp::Node'),
                          ('b::Talker', 'rclcpp::Node')],
        build_base=str(tmp_path / 'no_build'))
    # a registration whose names stay unknown (${plugin}) is left out; two
    # classes of one short name keep their qualified names
    assert components == {
        'Camera_node': 'demo::Camera',
        'a::Talker': 'a::Talker',
        'b::Talker': 'b::Talker',
    }


NODE = """#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
int main(int argc, char ** argv)
{{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("{name}");
  auto pub = node->create_publisher<std_msgs::msg::String>("{name}_out", 1);
  rclcpp::spin(node);
  return 0;
}}
"""


def test_a_program_no_executable_builds_is_no_node(tmp_path):
    package = tmp_path / 'src' / 'looped'
    (package / 'src').mkdir(parents=True)
    (package / 'package.xml').write_text(
        '<?xml version="1.0"?><package format="3"><name>looped</name>'
        '<version>0.0.1</version><description>d</description>'
        '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
        '<buildtool_depend>ament_cmake</buildtool_depend>'
        '<depend>rclcpp</depend>'
        '<export><build_type>ament_cmake</build_type></export></package>')
    # executables made in a loop (CMake reads it); gamma's main is built by
    # no executable
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(looped)\n'
        'foreach(node alpha beta)\n'
        '  add_executable(${node}_node src/${node}.cpp)\nendforeach()\n')
    for name in ('alpha', 'beta', 'gamma'):
        (package / 'src' / f'{name}.cpp').write_text(NODE.format(name=name))
    run_colcon(['rsia', 'analyze', '--base-paths', str(tmp_path / 'src')],
               cwd=tmp_path, check=True)
    summary = json.loads(
        (tmp_path / 'build' / 'looped' / 'rsia' / 'summary.json').read_text())
    # each built main is its own node with only its own publisher; the
    # one no target builds is in no running system: a note, no node
    nodes = {n['id']: [p['topic'] for p in n['publishers']]
             for n in summary['nodes']}
    assert nodes == {'looped/alpha_node': ['alpha_out'],
                     'looped/beta_node': ['beta_out']}
    assert summary['diagnostics'] == [
        'src/gamma.cpp: note: defines main() but no executable of '
        'CMakeLists.txt builds it: not a node']
    # and its publisher's call site is code the build never compiles, not
    # a call site the analysis missed
    recorded = {(c['file'], c['recorded'])
                for c in summary['coverage']['call_sites']}
    assert recorded == {('src/alpha.cpp', 'node'), ('src/beta.cpp', 'node'),
                        ('src/gamma.cpp', 'unread')}


def test_a_program_a_command_cmake_could_not_run_builds(tmp_path):
    package = tmp_path / 'src' / 'mapper'
    (package / 'mapper' / 'dev').mkdir(parents=True)
    (package / 'package.xml').write_text(
        '<?xml version="1.0"?><package format="3"><name>mapper</name>'
        '<version>0.0.1</version><description>d</description>'
        '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
        '<buildtool_depend>ament_cmake</buildtool_depend>'
        '<depend>rclcpp</depend>'
        '<export><build_type>ament_cmake</build_type></export></package>')
    # the command that makes executables comes from a library's CMake
    # module that is not there: CMake fails, the text reader knows no
    # such command; the sources lie in a subdirectory with its own
    # CMakeLists.txt
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(mapper)\n'
        'find_package(mapping_core REQUIRED)\n'
        'include("${MAPPING_CORE_CMAKE_DIR}/functions.cmake")\n'
        'add_subdirectory(mapper)\n')
    (package / 'mapper' / 'CMakeLists.txt').write_text(
        'mapping_binary(mapper_node\n  SRCS\n    node_main.cpp\n)\n')
    (package / 'mapper' / 'node_main.cpp').write_text(
        NODE.format(name='mapper'))
    # named by no command: no node, as before
    (package / 'mapper' / 'dev' / 'scratch_main.cpp').write_text(
        NODE.format(name='scratch'))
    run_colcon(['rsia', 'analyze', '--base-paths', str(tmp_path / 'src')],
               cwd=tmp_path, check=True)
    summary = json.loads(
        (tmp_path / 'build' / 'mapper' / 'rsia' / 'summary.json').read_text())
    nodes = {n['id']: [p['topic'] for p in n['publishers']]
             for n in summary['nodes']}
    assert nodes == {'mapper/mapper_node': ['mapper_out']}
    notes = [d for d in summary['diagnostics'] if ': note:' in d]
    assert notes == [
        'mapper/dev/scratch_main.cpp: note: defines main() but no executable '
        'of CMakeLists.txt builds it: not a node',
        'mapper/node_main.cpp: note: defines main() and CMakeLists.txt names '
        "it in a command CMake could not run here: node 'mapper_node' named "
        "after that command's first argument"]
