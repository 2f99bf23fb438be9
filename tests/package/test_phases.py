# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Where a package's analysis time went: the summary's ``phases``."""

from colcon_rsia.summary.package_summary import PackageSummary
from colcon_rsia.summary.store import read_summary
from colcon_rsia.summary.store import summary_path
from conftest import analyze_source
import pytest

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "talker");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("chatter", 1);
  ros::Rate rate(10);
  while (ros::ok()) { pub.publish(std_msgs::String()); rate.sleep(); }
}
"""


def test_the_phases_of_a_parsed_package_add_up_to_its_time(tmp_path):
    summary = analyze_source(tmp_path, 'talker', NODE)
    phases = summary.phases
    # a unit was parsed: that takes time; nothing is instantaneous
    assert phases.parse > 0
    assert phases.prepare >= 0 and phases.assemble >= 0
    assert phases.prepare + phases.parse + phases.assemble <= \
        summary.seconds + 0.01
    stored = read_summary(summary_path(str(tmp_path / 'b')))
    assert stored.phases == phases


@pytest.mark.parametrize('phases', [
    {'parse': 'slow'}, {'parse': float('nan')}, {'linking': 1.0}, [1.0]])
def test_malformed_phases_are_rejected_when_read(tmp_path, phases):
    data = analyze_source(tmp_path, 'talker', NODE).to_dict()
    data['phases'] = phases
    with pytest.raises(ValueError):
        PackageSummary.from_dict(data)
