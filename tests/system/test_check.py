# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""`colcon rsia check --bag`: recordings against the predicted rates.

The bags are written here with rosbags' writers (ROS 1, ROS 2 sqlite3 and
MCAP), at rates chosen against the system workspace's hand-derived graph
(test_workspaces/system/expected.yaml): /plan 5 Hz (planner's timer),
/odom 50 Hz (base_driver's Rate loop), /filter_stats 1 Hz (a timer).
"""

import json

from colcon_rsia.system.bags import BagError
from colcon_rsia.system.bags import measure_bag
from helpers import START_NS
from helpers import write_bag
import pytest


@pytest.mark.parametrize('storage', ['ros1', 'sqlite3', 'mcap'])
def test_rates_are_measured_in_every_storage(tmp_path, storage):
    name = 'run.bag' if storage == 'ros1' else 'run'
    bag = write_bag(tmp_path / name, {'/fast': 50.0, '/slow': 2.0}, storage)
    measured = measure_bag(bag)
    assert measured['/fast'].count == 201
    assert measured['/fast'].hz == pytest.approx(50.0)
    assert measured['/slow'].hz == pytest.approx(2.0)


def _check(workspace, *args, check=True):
    return workspace.colcon(
        'rsia', 'check', '--base-paths', str(workspace.src), *args,
        check=check)


def test_one_bag_each_topic_against_its_prediction(system_workspace,
                                                   tmp_path):
    bag = write_bag(tmp_path / 'run.bag', {
        '/plan': 5.0,            # the planner's 5 Hz timer
        '/odom': 30.0,           # predicted 50 Hz: outside 15 %
        '/rosout': 10.0,         # no analysed node publishes it
    })
    result = json.loads(_check(
        system_workspace, '--bag', str(bag), '--format', 'json').stdout)
    assert result['schema'] == 'colcon-rsia/check@1'
    topics = {t['name']: t for t in result['topics']}
    assert (topics['/plan']['status'], topics['/plan']['predicted_hz']) == \
        ('ok', 5.0)
    assert topics['/odom']['status'] == 'mismatch'
    assert topics['/odom']['before_hz'] == pytest.approx(30.0)
    assert topics['/odom']['predicted_hz'] == 50.0
    assert topics['/rosout']['status'] == 'unpredicted'
    assert topics['/filter_stats']['status'] == 'not recorded'
    text = _check(system_workspace, '--bag', str(bag)).stdout
    assert '/odom' in text and 'mismatch' in text


@pytest.mark.parametrize('storage', ['sqlite3', 'mcap'])
def test_two_bags_around_a_change(system_workspace, tmp_path, storage):
    before = write_bag(tmp_path / 'before', {
        '/odom': 50.0, '/base_status': 5.0, '/plan': 5.0,
        '/filter_stats': 1.0, '/rosout': 6.0}, storage)
    # base_driver changed: its odometry halves (predicted: it may); the
    # planner's timer-paced /plan also changes, which the model rules out;
    # the log lines on /rosout come from no analysed node's code
    after = write_bag(tmp_path / 'after', {
        '/odom': 25.0, '/base_status': 5.0, '/plan': 2.0,
        '/filter_stats': 1.0, '/rosout': 4.0}, storage)
    args = ['--bag', str(before), '--bag', str(after),
            '--changed', 'sysbot_drivers/base_driver']
    result = json.loads(_check(
        system_workspace, *args, '--format', 'json').stdout)
    topics = {t['name']: t for t in result['topics']}
    assert topics['/odom']['status'] == 'changed'
    assert topics['/odom']['predicted_to_change']
    assert topics['/filter_stats']['status'] == 'unchanged'
    # /plan changed although only an independent edge leads to it
    [miss] = result['unexpected_changes']
    assert miss['topic'] == '/plan'
    assert any('sysbot_navigation/planner -> /plan' in edge
               for edge in miss['kept_by']), miss
    assert result['changes_outside_the_model'] == [
        {'topic': '/rosout', 'before_hz': 6.0, 'after_hz': 4.0}]
    # base_driver's own /base_status could have changed; it did not
    assert [t['topic'] for t in result['predicted_but_unchanged']] == \
        ['/base_status']
    failed = _check(system_workspace, *args, '--fail-on-unexpected',
                    check=False)
    assert failed.returncode == 2
    assert 'did not predict: /plan' in failed.stderr


def test_two_bags_need_the_change(system_workspace, tmp_path):
    bag = write_bag(tmp_path / 'run.bag', {'/plan': 5.0})
    result = _check(system_workspace, '--bag', str(bag), '--bag', str(bag),
                    check=False)
    assert result.returncode == 1
    assert 'two bags need --changed or --since' in result.stderr


def _truncated(tmp_path):
    bag = write_bag(tmp_path / 'full.bag', {'/plan': 5.0})
    cut = tmp_path / 'truncated.bag'
    cut.write_bytes(bag.read_bytes()[:300])
    return cut


def _unknown_storage(tmp_path):
    path = tmp_path / 'notes.bag'
    path.write_text('not a bag at all\n')
    return path


def _empty(tmp_path):
    return write_bag(tmp_path / 'empty', {}, 'sqlite3')


def _no_timestamps(tmp_path):
    from rosbags.rosbag1 import Writer
    from rosbags.typesys import get_typestore
    from rosbags.typesys import Stores
    typestore = get_typestore(Stores.ROS1_NOETIC)
    msgtype = 'std_msgs/msg/String'
    data = typestore.serialize_ros1(typestore.types[msgtype](data='x'),
                                    msgtype)
    path = tmp_path / 'frozen.bag'
    with Writer(path) as writer:
        connection = writer.add_connection(
            '/plan', msgtype, typestore=typestore)
        for _ in range(5):
            writer.write(connection, START_NS, data)
    return path


@pytest.mark.parametrize('make,message', [
    (_truncated, 'cannot be read as a ROS 1 or ROS 2 bag'),
    (_unknown_storage, 'cannot be read as a ROS 1 or ROS 2 bag'),
    (_empty, 'the bag holds no message'),
    (_no_timestamps, 'no usable timestamps'),
    (lambda tmp_path: tmp_path / 'missing.bag', 'no such bag'),
])
def test_bad_bags_give_one_clear_message(tmp_path, make, message):
    path = make(tmp_path)
    with pytest.raises(BagError) as error:
        measure_bag(path)
    assert message in str(error.value)
    assert str(path) in str(error.value)
    assert '\n' not in str(error.value)


def test_a_bad_bag_on_the_command_line_is_one_line(
        system_workspace, tmp_path):
    result = _check(system_workspace, '--bag',
                    str(_unknown_storage(tmp_path)), check=False)
    assert result.returncode == 1
    assert 'Traceback' not in result.stderr
    assert 'cannot be read as a ROS 1 or ROS 2 bag' in result.stderr
