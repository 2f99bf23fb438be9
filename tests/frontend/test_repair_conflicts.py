# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A repair that clang rejects is withdrawn.

A unit starts with the names its package's other units needed. Where it
includes the real declaration of one, a message's typedef say, the
repair's class conflicts with it: the repair header itself has an error.
The unit then parses again without that repair. Expectations written by
hand from the code below.
"""

import json
from pathlib import Path

from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.summary.store import RSIA_DIRNAME
from conftest import analyze_source
import pytest

STAMPER = r"""
#include <ros/ros.h>
#include <std_msgs/Header.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "stamper");
  ros::NodeHandle nh;
  ros::Publisher stamps = nh.advertise<std_msgs::Header>("stamps", 1);
  ros::Timer timer = nh.createTimer(ros::Duration(0.1),
      [&](const ros::TimerEvent&) { stamps.publish(std_msgs::Header()); });
  ros::spin();
}
"""


@pytest.mark.parametrize('offered_header', [False, True], ids=[
    # the typedef comes after the repair: the error is at the typedef, its
    # note at the repair
    'typedef-after',
    # a header the repair header includes declares it first: the error is
    # in the repair header
    'typedef-before'])
def test_a_repair_conflicting_with_a_typedef_is_withdrawn(
        tmp_path, offered_header):
    # what other units of the package offered: one used the message's name
    # without including its header, one needed the header
    offered = Path(tmp_path, 'b', RSIA_DIRNAME, 'stubs',
                   store.REPAIR_DIR, store.SHARED_REPAIRS)
    offered.parent.mkdir(parents=True)
    offered.write_text(json.dumps(
        [['type', 'std_msgs::Header']] +
        [['header', 'std_msgs/Header.h']] * offered_header))

    summary = analyze_source(tmp_path, 'stamper', STAMPER, repair='when-it-pays')
    [unit] = summary.coverage.units
    # this unit includes the message, whose typedef the seeded class
    # conflicted with: one more parse, without it
    assert ['type', 'std_msgs::Header'] not in [
        [kind, name] for _, kind, name in unit.repairs]
    assert unit.repair_rounds == 1
    assert not [d for d in summary.diagnostics if store.REPAIR_DIR in d]
    [node] = summary.nodes
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('stamps', 'independent')]


def test_a_withdrawn_repair_is_offered_no_more(tmp_path):
    repair_dir = tmp_path / 'pkg' / store.REPAIR_DIR
    repair_dir.mkdir(parents=True)
    workspace = store.WorkspaceRepairs(str(tmp_path / 'workspace.json'),
                                       set())
    first = str(repair_dir / 'first.h')
    store.share_repairs(first, {
        ('type', 'std_msgs::Header'), ('type', 'gizmo::Lens')}, workspace)
    # a unit including the message's header rejected the class
    store.withdraw_shared(first, {('type', 'std_msgs::Header')}, workspace)
    # a unit seeded before shares what it started with: not that one
    store.share_repairs(first, {('type', 'std_msgs::Header')}, workspace)

    later = str(repair_dir / 'later.h')
    store.ensure_repair_header(later, 'src/later.cpp')
    store.seed_repairs(later, 'src/later.cpp', set(), workspace)
    assert store.read_repairs(later) == {('type', 'gizmo::Lens')}


POINTER_CLASS = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <vision/filters.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "equalizer");
  ros::NodeHandle nh;
  // a library the machine lacks, whose smart pointer is a class `Ptr`
  vision::Ptr<vision::Equalizer> equalizer = vision::createEqualizer(2.0);
  ros::Publisher out = nh.advertise<std_msgs::String>("equalized", 1);
  ros::spin();
}
"""


def test_a_catch_all_class_named_like_a_pointer_alias_compiles(tmp_path):
    summary = analyze_source(tmp_path, 'equalizer', POINTER_CLASS)
    # `vision::Ptr` is declared by the model mode (a stand-in of the
    # unknown namespace, or a repair): a class `Ptr` with a member `Ptr`
    # is no C++, and what the model mode writes must compile
    assert not [d for d in summary.diagnostics
                if f'{RSIA_DIRNAME}/stubs/' in d]
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['equalized']
