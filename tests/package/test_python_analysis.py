# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The analysis of the Python test workspace against hand-written files.

Nothing is built: the Python front end reads the sources where they are.
"""

import re
import shutil

from colcon_rsia.package.python_analysis import analyze_python_package
from colcon_rsia.package.python_nodes import find_python_nodes
from colcon_rsia.summary.store import read_summary
from conftest import build_workspace
from conftest import WORKSPACES
from helpers import read_yaml
from projection import check_evidence
from projection import project_nodes
import pytest

SRC = WORKSPACES / 'python' / 'src'
EXPECTED = sorted((WORKSPACES / 'python' / 'expected').glob('*.yaml'))
SECTIONS = ('publishers', 'subscribers', 'timers', 'services', 'actions')
PUBLISH_WORDS = re.compile(r'publish|sendTransform')


def _analyze(package_path, build_base, name=None):
    summary = analyze_python_package(
        name=name or package_path.name, path=str(package_path),
        build_base=str(build_base))
    return summary.to_dict()


def _assert_matches(got_nodes, expected):
    want = project_nodes(expected.get('nodes') or [])
    got = project_nodes(got_nodes)
    assert sorted(got) == sorted(want), 'node ids differ'
    for node_id in sorted(want):
        for section in SECTIONS:
            assert got[node_id][section] == want[node_id][section], \
                f'{node_id} {section}'
        assert got[node_id]['kind'] == want[node_id]['kind'], node_id


@pytest.mark.parametrize('path', EXPECTED, ids=[p.stem for p in EXPECTED])
def test_package_matches_expected_file(tmp_path, path):
    expected = read_yaml(path)
    build_base = tmp_path / expected['package']
    summary = _analyze(SRC / expected['package'], build_base)
    assert summary['diagnostics'] == []
    _assert_matches(summary['nodes'], expected)
    # the summary on disk is the one returned
    stored = read_summary(str(build_base / 'rsia' / 'summary.json'))
    assert stored.to_dict() == summary


def test_expected_files_cover_every_package():
    packages = {p.parent.name for p in SRC.glob('*/package.xml')}
    assert packages == {read_yaml(p)['package'] for p in EXPECTED}


def test_every_label_has_evidence_pointing_at_code(tmp_path):
    checked = 0
    for path in EXPECTED:
        package = read_yaml(path)['package']
        summary = _analyze(SRC / package, tmp_path / package)
        checked += check_evidence(summary, PUBLISH_WORDS)
    assert checked > 0


def test_entry_module_and_entry_function_are_main_roots(tmp_path):
    ros1 = _analyze(SRC / 'rsia_py_ros1', tmp_path / 'ros1')
    driver = next(n for n in ros1['nodes']
                  if n['executable'] == 'sensor_driver.py')
    assert {'function': '<module>', 'kind': 'main',
            'location': 'scripts/sensor_driver.py:1'} in driver['roots']
    ros2 = _analyze(SRC / 'rsia_py_ros2', tmp_path / 'ros2')
    heartbeat = next(n for n in ros2['nodes']
                     if n['executable'] == 'heartbeat')
    assert {'function': 'run', 'kind': 'main',
            'location': 'rsia_py_ros2/heartbeat.py:29'} in heartbeat['roots']
    assert heartbeat['sources'] == ['rsia_py_ros2/heartbeat.py']


def _catkin_package(root, name):
    root.mkdir(parents=True)
    (root / 'package.xml').write_text(
        '<?xml version="1.0"?>\n<package format="2">\n'
        f'  <name>{name}</name>\n  <version>0.0.1</version>\n'
        '  <description>test</description>\n'
        '  <maintainer email="a@b.c">a</maintainer>\n'
        '  <license>BSD</license>\n'
        '  <buildtool_depend>catkin</buildtool_depend>\n</package>\n')
    (root / 'CMakeLists.txt').write_text(
        f'cmake_minimum_required(VERSION 3.10)\nproject({name})\n'
        'find_package(catkin REQUIRED)\ncatkin_package()\n')
    (root / 'scripts').mkdir()
    return root


def test_analyzed_code_is_never_run(tmp_path):
    marker = tmp_path / 'ran.txt'
    package = _catkin_package(tmp_path / 'src' / 'writer_pkg', 'writer_pkg')
    (package / 'scripts' / 'helper.py').write_text(
        f'open({str(marker)!r}, "w").write("imported")\n'
        'import rospy\n'
        'def beat(pub):\n'
        '    pub.publish()\n')
    (package / 'scripts' / 'writer').write_text(
        '#!/usr/bin/env python3\n'
        f'open({str(marker)!r}, "w").write("ran")\n'
        'import rospy\n'
        'from std_msgs.msg import Empty\n'
        'import helper\n'
        'raise SystemExit("never run")\n'
        'pub = rospy.Publisher("beat", Empty, queue_size=1)\n'
        'rospy.Timer(rospy.Duration(0.25), lambda event: helper.beat(pub))\n'
        'rospy.Subscriber("poke", Empty, lambda msg: None)\n')
    summary = _analyze(package, tmp_path / 'build')
    assert not marker.exists()
    assert summary['diagnostics'] == []
    [node] = summary['nodes']
    assert node['id'] == 'writer_pkg/writer'
    [publisher] = node['publishers']
    assert (publisher['topic'], publisher['label'], publisher['pattern'],
            publisher['rate_hz']) == ('beat', 'independent', 'timer', 4.0)
    assert publisher['publish_sites'] == ['scripts/helper.py:4']


BROKEN = {
    'syntax_error': (b'#!/usr/bin/env python3\nimport rospy\n'
                     b'def main(:\n    pass\n', 'syntax error at line 3'),
    'not_utf8': (b'#!/usr/bin/env python3\nimport rospy\n'
                 b'NAME = "caf\xe9"\n', 'not valid UTF-8 text'),
}


@pytest.mark.parametrize('kind', sorted(BROKEN))
def test_unparsable_file_gives_one_diagnostic_and_other_nodes(tmp_path, kind):
    content, message = BROKEN[kind]
    package = tmp_path / 'rsia_py_ros1'
    shutil.copytree(SRC / 'rsia_py_ros1', package)
    broken = package / 'scripts' / 'broken.py'
    broken.write_bytes(content)
    summary = _analyze(package, tmp_path / 'build')
    [diagnostic] = summary['diagnostics']
    assert diagnostic.startswith('scripts/broken.py: '), diagnostic
    assert message in diagnostic
    assert "not analysed: node 'broken.py'" in diagnostic
    _assert_matches(
        summary['nodes'], read_yaml(
            WORKSPACES / 'python' / 'expected' / 'rsia_py_ros1.yaml'))


def test_broken_helper_module_leaves_its_importers_analyzed(tmp_path):
    package = tmp_path / 'rsia_py_ros1'
    shutil.copytree(SRC / 'rsia_py_ros1', package)
    util = package / 'src' / 'rsia_py_ros1' / 'util.py'
    util.write_text('def publish_status(publisher, text)\n')
    summary = _analyze(package, tmp_path / 'build')
    [diagnostic] = summary['diagnostics']
    assert diagnostic.startswith(
        'src/rsia_py_ros1/util.py: syntax error at line 1: '), diagnostic
    lidar = next(n for n in summary['nodes']
                 if n['executable'] == 'lidar_filter')
    topics = {p['topic']: p['label'] for p in lidar['publishers']}
    # the publish in the broken helper is not seen: dependent, no site
    assert topics == {'scan_filtered': 'independent',
                      'scan_echo': 'dependent', 'filter_state': 'dependent'}


def test_setup_cfg_entry_points_and_install_programs(tmp_path):
    ament = tmp_path / 'cfg_pkg'
    (ament / 'cfg_pkg').mkdir(parents=True)
    (ament / 'package.xml').write_text(
        '<package format="3"><name>cfg_pkg</name><export>'
        '<build_type>ament_python</build_type></export></package>')
    (ament / 'cfg_pkg' / '__init__.py').write_text('')
    (ament / 'cfg_pkg' / 'node.py').write_text('def start():\n    pass\n')
    (ament / 'setup.cfg').write_text(
        '[options.entry_points]\nconsole_scripts =\n'
        '    talker = cfg_pkg.node:start\n'
        '    missing = cfg_pkg.nowhere:main\n')
    layout = find_python_nodes(str(ament))
    assert [(n.executable, n.module, n.function) for n in layout.nodes] == \
        [('talker', 'cfg_pkg.node', 'start')]
    assert len(layout.problems) == 1 and 'missing' in layout.problems[0]

    cmake = tmp_path / 'cmake_pkg'
    (cmake / 'tools').mkdir(parents=True)
    (cmake / 'package.xml').write_text(
        '<package format="3"><name>cmake_pkg</name><export>'
        '<build_type>ament_cmake</build_type></export></package>')
    (cmake / 'CMakeLists.txt').write_text(
        'project(cmake_pkg)\n'
        'install(PROGRAMS tools/relay.py DESTINATION lib/${PROJECT_NAME})\n'
        '# install(PROGRAMS tools/old.py DESTINATION lib/${PROJECT_NAME})\n'
        '#[[ retired:\n'
        'install(PROGRAMS tools/old.py DESTINATION lib/${PROJECT_NAME})\n'
        ']]\n'
        'install(PROGRAMS tools/run.sh DESTINATION lib/${PROJECT_NAME})\n')
    for name in ('relay.py', 'old.py'):
        (cmake / 'tools' / name).write_text('print(1)\n')
    (cmake / 'tools' / 'run.sh').write_text('#!/bin/sh\n')
    layout = find_python_nodes(str(cmake))
    assert [(n.executable, n.module) for n in layout.nodes] == \
        [('relay.py', 'relay')]


def test_uninstalled_ros_scripts_are_nodes_run_from_source(tmp_path):
    """A plotting tool nobody installs is still a node its author runs."""
    package = tmp_path / 'tools_pkg'
    node_script = (
        '#!/usr/bin/env python3\n'
        'import rclpy\n'
        'from rclpy.node import Node\n'
        'from std_msgs.msg import Float32\n\n\n'
        'class Plotter(Node):\n'
        '    def __init__(self):\n'
        "        super().__init__('speed_plotter')\n"
        '        self.create_subscription(\n'
        "            Float32, 'speed', self.on_speed, 10)\n\n"
        '    def on_speed(self, msg):\n'
        '        pass\n\n\n'
        "if __name__ == '__main__':\n"
        '    rclpy.init()\n'
        '    rclpy.spin(Plotter())\n')
    _write(package, {
        'package.xml': (
            '<package format="3"><name>tools_pkg</name><export>'
            '<build_type>ament_cmake</build_type></export></package>'),
        'CMakeLists.txt': 'project(tools_pkg)\n',
        'script/plot_speed.py': node_script,
        # no shebang: imported, never run by itself
        'script/plot_lib.py': node_script.split('\n', 1)[1],
        # a shebang and a guard, but no ROS: a tool, not a node
        'script/convert.py': (
            "#!/usr/bin/env python3\nif __name__ == '__main__':\n"
            '    print(1)\n'),
        # the tests' scripts and a Python package's modules are not nodes
        'test/fake_publisher.py': node_script,
        'tools_pkg/__init__.py': '',
        'tools_pkg/cli.py': node_script,
        # a package inside this one: its scripts are its own
        'nested_pkg/package.xml': '<package><name>nested_pkg</name></package>',
        'nested_pkg/scripts/talker.py': node_script,
    })
    layout = find_python_nodes(str(package))
    assert [(n.executable, n.installed) for n in layout.nodes] == \
        [('plot_speed.py', False)]
    summary = _analyze(package, tmp_path / 'build')
    (node,) = summary['nodes']
    assert (node['id'], node['name']) == \
        ('tools_pkg/plot_speed.py', 'speed_plotter')
    assert [(s['topic'], s['callback']) for s in node['subscribers']] == \
        [('speed', 'Plotter.on_speed')]
    assert summary['diagnostics'] == [
        'script/plot_speed.py: note: not installed; analysed as the node '
        "'plot_speed.py' run from the source tree"]


def _write(root, files):
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


def _publishers(summary, executable):
    node = next(n for n in summary['nodes'] if n['executable'] == executable)
    return {p['topic']: (p['label'], p['pattern'], p['rate_hz'],
                         p['publish_sites']) for p in node['publishers']}


def test_overrides_and_hooks_reach_only_the_nodes_that_load_them(tmp_path):
    package = tmp_path / 'hooks_pkg'
    _write(package, {
        'package.xml': '<package format="3"><name>hooks_pkg</name><export>'
                       '<build_type>ament_python</build_type></export>'
                       '</package>',
        'setup.cfg': '[options.entry_points]\nconsole_scripts =\n'
                     '    plain = hooks_pkg.base:main\n'
                     '    derived = hooks_pkg.derived:main\n',
        'hooks_pkg/__init__.py': '',
        'hooks_pkg/base.py': (
            'import rclpy\n'
            'from rclpy.node import Node\n'
            'from std_msgs.msg import String\n'
            'class Base(Node):\n'
            '    def __init__(self, name):\n'
            '        super().__init__(name)\n'
            '        self.out = self.create_publisher(String, "out", 1)\n'
            '        self.echo = self.create_publisher(String, "echo", 1)\n'
            '        self.create_timer(0.5, self.tick)\n'
            '        self.create_subscription(String, "in", self.on_in, 1)\n'
            '    def tick(self):\n'
            '        self.step()\n'
            '    def on_in(self, msg):\n'
            '        self.react(msg)\n'
            '    def react(self, msg):\n'
            '        pass\n'
            'def main():\n'
            '    rclpy.spin(Base("plain"))\n'),
        'hooks_pkg/derived.py': (
            'import rclpy\n'
            'from std_msgs.msg import String\n'
            'from hooks_pkg.base import Base\n'
            'class Derived(Base):\n'
            '    def step(self):\n'
            '        self.out.publish(String())\n'
            '    def react(self, msg):\n'
            '        self.echo.publish(msg)\n'
            'def main():\n'
            '    rclpy.spin(Derived("derived"))\n'),
    })
    summary = _analyze(package, tmp_path / 'build')
    assert summary['diagnostics'] == []
    # step() exists only in the subclass (a hook the base calls), react()
    # overrides the base's: both run in the derived node only
    assert _publishers(summary, 'derived') == {
        'out': ('independent', 'timer', 2.0, ['hooks_pkg/derived.py:6']),
        'echo': ('dependent', 'none', None, ['hooks_pkg/derived.py:8'])}
    assert _publishers(summary, 'plain') == {
        'out': ('dependent', 'none', None, []),
        'echo': ('dependent', 'none', None, [])}


def test_rospy_details(tmp_path):
    package = _catkin_package(tmp_path / 'details_pkg', 'details_pkg')
    _write(package, {
        'src/details_pkg/__init__.py': '',
        'src/details_pkg/helpers.py': 'HZ = 5\n',
        # named like the package: `from details_pkg import` is the package
        'scripts/details_pkg': (
            '#!/usr/bin/env python3\n'
            'import rospy\n'
            'from std_msgs.msg import String\n'
            'from details_pkg import helpers\n'
            'def on_msg(msg, pub):\n'
            '    pub.publish(msg)\n'
            'def main():\n'
            '    echo = rospy.Publisher("echo", String, queue_size=1)\n'
            '    fresh = rospy.Publisher("fresh", String, queue_size=1)\n'
            '    paced = rospy.Publisher("paced", String, queue_size=1)\n'
            '    rospy.Subscriber("in", String, on_msg, callback_args=echo)\n'
            '    for _ in range(10):\n'
            '        fresh.publish(String())\n'
            '        rospy.Rate(helpers.HZ).sleep()\n'
            '    rate = rospy.Rate(helpers.HZ)\n'
            '    while not rospy.is_shutdown():\n'
            '        paced.publish(String())\n'
            '        rate.sleep()\n'
            'main()\n'),
    })
    summary = _analyze(package, tmp_path / 'build')
    assert summary['diagnostics'] == []
    assert _publishers(summary, 'details_pkg') == {
        # the callback_args publisher is the callback's second parameter
        'echo': ('dependent', 'none', None, ['scripts/details_pkg:6']),
        # a Rate made in every iteration never adapts
        'fresh': ('dependent', 'none', None, ['scripts/details_pkg:13']),
        'paced': ('independent', 'rate_loop', 5.0,
                  ['scripts/details_pkg:17'])}


@pytest.fixture(scope='module')
def python_workspace(tmp_path_factory):
    """test_workspaces/python built by colcon with the rsia handler."""
    workspace = build_workspace(SRC, tmp_path_factory.mktemp('python_ws'))
    assert workspace.returncode == 0, workspace.stdout + workspace.stderr
    return workspace


@pytest.mark.parametrize('path', EXPECTED, ids=[p.stem for p in EXPECTED])
def test_event_handler_analyzes_python_packages(python_workspace, path):
    expected = read_yaml(path)
    assert f"rsia: {expected['package']}: " in python_workspace.stdout
    _assert_matches(
        python_workspace.summary(expected['package'])['nodes'], expected)


def test_node_names_come_from_the_code(tmp_path):
    # written from rospy.init_node('...'), rclpy.create_node('...') and
    # super().__init__('...') of each node (or of its base class)
    expected = {
        'rsia_py_ros1/aligner.py': 'aligner',
        'rsia_py_ros1/cmd_repeater.py': 'cmd_repeater',
        'rsia_py_ros1/lidar_filter': 'lidar_filter',
        'rsia_py_ros1/odom_relay.py': 'odom_relay',
        'rsia_py_ros1/sensor_driver.py': 'sensor_driver',
        'rsia_py_ros2/fusion': 'fusion',
        'rsia_py_ros2/heartbeat': 'heartbeat',
        'rsia_py_ros2/mission_server': 'mission_server',
        'rsia_py_ros2/planner': 'planner',
        'rsia_py_ros2/pose_broadcaster': 'pose_broadcaster',
        # UltrasonicNode passes 'ultrasonic' to a base class of the package
        # that hands its parameter on to Node
        'rsia_py_ros2/ultrasonic': 'ultrasonic',
    }
    names = {}
    for package in ('rsia_py_ros1', 'rsia_py_ros2'):
        summary = _analyze(SRC / package, tmp_path / package)
        names.update({n['id']: n['name'] for n in summary['nodes']})
    assert names == expected


def test_service_clients_are_recorded(tmp_path):
    # self.create_client(Trigger, 'get_version') in heartbeat.py and
    # (Trigger, 'lights_on') in mission_server.py; no other node has one
    summary = _analyze(SRC / 'rsia_py_ros2', tmp_path)
    clients = {
        n['id']: [(c['name'], c['api'], c['location']) for c in n['clients']]
        for n in summary['nodes'] if n['clients']}
    api = 'rclpy.node.Node.create_client'
    assert clients == {
        'rsia_py_ros2/heartbeat': [
            ('get_version', api, 'rsia_py_ros2/heartbeat.py:22')],
        'rsia_py_ros2/mission_server': [
            ('lights_on', api, 'rsia_py_ros2/mission_server.py:33')],
    }


def test_the_client_librarys_own_scripts_call_its_api(tmp_path):
    """In the client library's own package, `rospy.X` is still the API."""
    package = _catkin_package(tmp_path / 'rospy', 'rospy')
    _write(package, {
        'setup.py': '',
        # the library's implementation, which the table models
        'src/rospy/__init__.py': 'from rospy.topics import Publisher\n',
        'src/rospy/topics.py': (
            'class Publisher(object):\n'
            '    def __init__(self, name, data_class, queue_size=None):\n'
            '        self.name = name\n\n'
            '    def publish(self, message):\n'
            '        pass\n'),
        'test_nodes/talker.py': (
            '#!/usr/bin/env python\n'
            'import rospy\n'
            'from std_msgs.msg import String\n\n\n'
            'def talker():\n'
            "    rospy.init_node('talker', anonymous=True)\n"
            "    pub = rospy.Publisher('chatter', String, queue_size=10)\n"
            '    rate = rospy.Rate(10)\n'
            '    while not rospy.is_shutdown():\n'
            "        pub.publish('hello')\n"
            '        rate.sleep()\n\n\n'
            "if __name__ == '__main__':\n"
            '    talker()\n'),
    })
    summary = _analyze(package, tmp_path / 'build')
    [node] = [n for n in summary['nodes'] if n['executable'] == 'talker.py']
    assert [(p['topic'], p['label'], p['pattern']) for p in node['publishers']] \
        == [('chatter', 'independent', 'no_subscribers')]
