# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The Python nodes of a CMake package (ament_cmake_python).

``ament_python_install_package(<pkg> SETUP_CFG <pkg>/setup.cfg ...)``
installs the package's Python package with the console_scripts of that
setup.cfg as executables. Expectations written from the files below.
"""

from colcon_rsia.package import runner
from colcon_rsia.package.python_nodes import find_python_nodes

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(relays)
find_package(ament_cmake REQUIRED)
find_package(ament_cmake_python REQUIRED)
ament_python_install_package(${PROJECT_NAME}
  SETUP_CFG
    ${PROJECT_NAME}/setup.cfg
  SCRIPTS_DESTINATION
    lib/${PROJECT_NAME}
)
ament_package()
"""
SETUP_CFG = """[options.entry_points]
console_scripts =
    relay_any = relays.relay_any:main
"""
PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>relays</name><version>0.0.1</version><description>x</description>
  <maintainer email="someone@example.com">someone</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""
# the message class and the topic come from the command line: the
# endpoints exist, their names are not known
RELAY = """import rclpy
from rclpy.node import Node


class RelayAny(Node):

    def __init__(self, args):
        super().__init__('relay_any')
        self.pub = self.create_publisher(args.klass, args.output, 10)
        self.sub = self.create_subscription(
            args.klass, args.input, self.forward, 10)

    def forward(self, msg):
        self.pub.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(RelayAny(None))
"""


def _package(tmp_path):
    package = tmp_path / 'relays'
    (package / 'relays').mkdir(parents=True)
    (package / 'CMakeLists.txt').write_text(CMAKE)
    (package / 'package.xml').write_text(PACKAGE_XML)
    (package / 'relays' / '__init__.py').write_text('')
    (package / 'relays' / 'setup.cfg').write_text(SETUP_CFG)
    (package / 'relays' / 'relay_any.py').write_text(RELAY)
    return package


def test_the_entry_points_of_an_installed_python_package(tmp_path):
    layout = find_python_nodes(str(_package(tmp_path)))
    assert [(n.executable, n.module, n.function) for n in layout.nodes] == [
        ('relay_any', 'relays.relay_any', 'main')]


def test_they_are_nodes_of_the_cmake_package(tmp_path):
    package = _package(tmp_path)
    outcome = runner.analyze(
        name='relays', package_type='ros.ament_cmake', path=str(package),
        build_base=str(tmp_path / 'build' / 'relays'), without_build=True,
        workspace_package_dirs=[str(package)])
    assert outcome.error is None, outcome.error
    [node] = outcome.summary.nodes
    assert node.id == 'relays/relay_any'
    [publisher] = node.publishers
    assert (publisher.topic, publisher.topic_is_literal, publisher.label) \
        == ('args.output', False, 'dependent')
    assert [s.topic for s in node.subscribers] == ['args.input']
