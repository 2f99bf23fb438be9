# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Publishers kept in a container, published through a range-for loop.

``for (auto& pub : pubs_) pub.publish(m)`` publishes through every
publisher the container holds: the loop's variable stands for the
container's elements. Expectations written by hand from the code below.
"""

from conftest import analyze_source

AXES = r"""
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>
#include <string>
#include <vector>

class Axes
{
public:
  explicit Axes(ros::NodeHandle& nh)
  {
    for (const std::string& axis : {"x", "y"})
    {
      velocity_pubs_.push_back(
          nh.advertise<std_msgs::Float64>("velocity_" + axis, 1));
      effort_pubs_.push_back(
          nh.advertise<std_msgs::Float64>("effort_" + axis, 1));
    }
    command_sub_ = nh.subscribe("command", 1, &Axes::onCommand, this);
    timer_ = nh.createTimer(ros::Duration(0.02), &Axes::onTimer, this);
  }

private:
  void onTimer(const ros::TimerEvent&)
  {
    for (auto& pub : velocity_pubs_)
    {
      pub.publish(std_msgs::Float64());
    }
  }
  void onCommand(const std_msgs::String::ConstPtr&)
  {
    for (ros::Publisher& effort : effort_pubs_)
    {
      effort.publish(std_msgs::Float64());
    }
  }
  std::vector<ros::Publisher> velocity_pubs_, effort_pubs_;
  ros::Subscriber command_sub_;
  ros::Timer timer_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "axes");
  ros::NodeHandle nh;
  Axes axes(nh);
  ros::spin();
}
"""


def test_a_range_for_publishes_through_the_containers_publishers(tmp_path):
    summary = analyze_source(tmp_path, 'axes', AXES)
    [node] = summary.nodes
    labels = {p.location: (p.label, p.rate_hz, p.publish_sites)
              for p in node.publishers}
    assert labels == {
        # velocity_<axis>: published by the 50 Hz timer's loop
        'src/axes.cpp:16': ('independent', 50.0, ['src/axes.cpp:29']),
        # effort_<axis>: published in the command subscription's callback
        'src/axes.cpp:18': ('dependent', None, ['src/axes.cpp:36']),
    }
    [effort] = [p for p in node.publishers if p.location == 'src/axes.cpp:18']
    assert [t.name for t in effort.triggers] == ['command']


AXES_PY = """\
#!/usr/bin/env python
import rospy
from std_msgs.msg import Float64, String


class Axes(object):
    def __init__(self):
        self.velocity_pubs = [
            rospy.Publisher('velocity_' + a, Float64, queue_size=1)
            for a in ('x', 'y')]
        self.effort_pubs = {}
        for a in ('x', 'y'):
            self.effort_pubs[a] = rospy.Publisher(
                'effort_' + a, Float64, queue_size=1)
        rospy.Subscriber('command', String, self.on_command)
        rospy.Timer(rospy.Duration(0.02), self.on_timer)

    def on_timer(self, event):
        for pub in self.velocity_pubs:
            pub.publish(Float64())

    def on_command(self, msg):
        for name, pub in self.effort_pubs.items():
            pub.publish(Float64())


if __name__ == '__main__':
    rospy.init_node('axes')
    Axes()
    rospy.spin()
"""


def test_a_python_loop_publishes_through_the_containers_publishers(
        tmp_path):
    from colcon_rsia.package.python_analysis import analyze_python_package
    package = tmp_path / 'axes'
    (package / 'scripts').mkdir(parents=True)
    (package / 'scripts' / 'axes.py').write_text(AXES_PY)
    (package / 'package.xml').write_text(
        '<package format="2"><name>axes</name></package>')
    summary = analyze_python_package(
        name='axes', path=str(package), build_base=str(tmp_path / 'build'))
    [node] = summary.nodes
    labels = {p.location: (p.label, p.rate_hz, p.publish_sites)
              for p in node.publishers}
    assert labels == {
        'scripts/axes.py:9': ('independent', 50.0, ['scripts/axes.py:20']),
        'scripts/axes.py:13': ('dependent', None, ['scripts/axes.py:24']),
    }
