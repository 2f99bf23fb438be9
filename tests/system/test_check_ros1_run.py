# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""End to end on a real run of the system workspace with ROS 1.

Started with Debian's ROS 1 runtime, recorded with `rosbag record`,
changed, recorded again. The change: laser_driver rebuilt with its Rate loop at 5 Hz instead of
10 Hz. Written by hand from test_workspaces/system (expected.yaml): the
change reaches /scan_filtered (scan_filter publishes it per /scan
message) and nothing else; /filter_stats (timer), /plan (timer), /odom
(Rate loop) and /image (timer) are independent edges and keep their
rates. Every process is started here, stopped by its id, and talks over
loopback only.
"""

import json
import os
import shutil
import socket
import subprocess
import time
import xmlrpc.client

from conftest import build_workspace
import pytest

pytestmark = pytest.mark.skipif(
    not (shutil.which('rosmaster') and shutil.which('rosbag')),
    reason='needs rosmaster and rosbag (.ci/install installs '
           'python3-rosmaster and python3-rosbag)')

NODES = {
    'sysbot_drivers': ('laser_driver', 'camera_driver', 'base_driver'),
    'sysbot_perception': ('scan_filter', 'obstacle_detector'),
    'sysbot_navigation': ('planner', 'controller', 'system_monitor'),
}
RECORD_SECONDS = 3


def _free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def _record(install, bag, tmp_path, laser_driver):
    """Run master and nodes, record every topic, stop them all."""
    port = _free_port()
    env = dict(os.environ, ROS_MASTER_URI=f'http://127.0.0.1:{port}',
               ROS_IP='127.0.0.1', ROS_HOME=str(tmp_path / 'ros_home'))
    env.pop('ROS_HOSTNAME', None)
    processes = []

    def start(command):
        processes.append(subprocess.Popen(
            command, env=env, stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL))
    try:
        start(['rosmaster', '--core', '-p', str(port)])
        master = xmlrpc.client.ServerProxy(env['ROS_MASTER_URI'])
        deadline = time.monotonic() + 10
        while True:
            try:
                master.getPid('/rsia_test')
                break
            except OSError:
                assert time.monotonic() < deadline, 'rosmaster did not start'
                time.sleep(0.1)
        for package, executables in NODES.items():
            for executable in executables:
                path = laser_driver if executable == 'laser_driver' else \
                    install / package / 'lib' / package / executable
                start([str(path)])
        subprocess.run(
            ['rosbag', 'record', '-a', '-q', '-O', str(bag),
             f'--duration={RECORD_SECONDS}'],
            env=env, check=True, timeout=RECORD_SECONDS + 20,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    finally:
        for process in processes:
            process.terminate()
        for process in processes:
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
    return bag


def test_a_real_run_changes_only_what_the_model_predicts(
        system_workspace, tmp_path):
    started = time.monotonic()
    install = system_workspace.root / 'install'
    # the change: laser_driver's Rate loop at 5 Hz, rebuilt apart
    changed_src = tmp_path / 'src'
    shutil.copytree(system_workspace.src / 'sysbot_drivers',
                    changed_src / 'sysbot_drivers')
    source = changed_src / 'sysbot_drivers' / 'src' / 'laser_driver.cpp'
    text = source.read_text()
    assert 'ros::Rate rate(10.0);' in text
    source.write_text(text.replace('ros::Rate rate(10.0);',
                                   'ros::Rate rate(5.0);'))
    changed = build_workspace(changed_src, tmp_path / 'changed',
                              handler=False)
    assert changed.returncode == 0, changed.stdout + changed.stderr
    new_laser_driver = tmp_path / 'changed' / 'install' / 'sysbot_drivers' / \
        'lib' / 'sysbot_drivers' / 'laser_driver'

    before = _record(install, tmp_path / 'before.bag', tmp_path,
                     install / 'sysbot_drivers' / 'lib' / 'sysbot_drivers' /
                     'laser_driver')
    after = _record(install, tmp_path / 'after.bag', tmp_path,
                    new_laser_driver)

    result = system_workspace.colcon(
        'rsia', 'check', '--base-paths', str(system_workspace.src),
        '--bag', str(before), '--bag', str(after),
        '--changed', 'sysbot_drivers/laser_driver', '--format', 'json',
        '--fail-on-unexpected', check=False)
    check = json.loads(result.stdout)
    topics = {t['name']: t for t in check['topics']}
    # soundness: nothing changed that the model did not predict
    assert check['unexpected_changes'] == [], check['unexpected_changes']
    assert result.returncode == 0, result.stderr
    # the change itself, and the one topic following it
    assert topics['/scan']['before_hz'] == pytest.approx(10, rel=0.1)
    assert topics['/scan']['after_hz'] == pytest.approx(5, rel=0.1)
    assert topics['/scan_filtered']['status'] == 'changed'
    assert topics['/scan_filtered']['predicted_to_change']
    # the independent edges held their rates
    for name, hz in (('/filter_stats', 1), ('/plan', 5), ('/odom', 50),
                     ('/image', 20)):
        assert topics[name]['status'] == 'unchanged', topics[name]
        assert topics[name]['after_hz'] == pytest.approx(hz, rel=0.1)
    assert time.monotonic() - started < 90
