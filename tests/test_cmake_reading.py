# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Which executables and components a package's CMakeLists.txt makes.

Without a build there is no CMake codemodel: the file itself is read, with
the helper functions and macros packages wrap add_executable in.
"""

import json

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


def test_helper_functions_macros_and_variables_are_expanded(tmp_path):
    (tmp_path / 'CMakeLists.txt').write_text(CMAKELISTS)
    executables = find_executables(
        package_path=str(tmp_path), build_base=str(tmp_path / 'no_build'))
    assert executables == {
        'talker': [str(tmp_path / 'src' / 'topics' / 'talker.cpp')],
        'server': [str(tmp_path / 'src' / 'services' / 'server.cpp')],
        'demo_tool': [str(tmp_path / 'src' / 'tool.cpp')],
    }
    components = find_components(
        package_path=str(tmp_path),
        exported_classes=[('a::Talker', 'rclcpp::Node'),
                          ('b::Talker', 'rclcpp::Node')])
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


def test_a_program_no_executable_names_is_its_own_node(tmp_path):
    package = tmp_path / 'src' / 'looped'
    (package / 'src').mkdir(parents=True)
    (package / 'package.xml').write_text(
        '<?xml version="1.0"?><package format="3"><name>looped</name>'
        '<version>0.0.1</version><description>d</description>'
        '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
        '<buildtool_depend>ament_cmake</buildtool_depend>'
        '<depend>rclcpp</depend>'
        '<export><build_type>ament_cmake</build_type></export></package>')
    # executables made in a loop: not readable without CMake itself
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(looped)\n'
        'foreach(node alpha beta)\n'
        '  add_executable(${node} src/${node}.cpp)\nendforeach()\n')
    for name in ('alpha', 'beta'):
        (package / 'src' / f'{name}.cpp').write_text(NODE.format(name=name))
    run_colcon(['rsia', 'analyze', '--base-paths', str(tmp_path / 'src')],
               cwd=tmp_path, check=True)
    summary = json.loads(
        (tmp_path / 'build' / 'looped' / 'rsia' / 'summary.json').read_text())
    # each main is its own node with only its own publisher, and says why
    nodes = {n['id']: [p['topic'] for p in n['publishers']]
             for n in summary['nodes']}
    assert nodes == {'looped/alpha': ['alpha_out'],
                     'looped/beta': ['beta_out']}
    assert len(summary['diagnostics']) == 2
    assert all('defines main() but no executable' in d
               for d in summary['diagnostics'])
