# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Clocks beyond ROS read in model mode: what is not a clock.

The clocks themselves are in test_workspaces/ros1/src/rsia_clocks (compiled
for real); expectations here are written by hand from the code below.
"""

from conftest import analyze_source

WATCHDOG = r"""
#include <QCoreApplication>
#include <QObject>
#include <QTimer>
#include <ros/ros.h>
#include <std_msgs/Empty.h>

// a class of the package with a timeout() signal of its own: it fires
// when a watched input goes quiet, not periodically
class Watchdog : public QObject
{
  Q_OBJECT

signals:
  void timeout();
};

class Monitor : public QObject
{
  Q_OBJECT

public:
  Monitor(ros::NodeHandle & nh, Watchdog * watchdog)
  {
    alarm_pub_ = nh.advertise<std_msgs::Empty>("alarm", 1);
    input_sub_ = nh.subscribe("input", 1, &Monitor::onInput, this);
    connect(watchdog, SIGNAL(timeout()), this, SLOT(onQuiet()));
  }

private slots:
  void onQuiet() { alarm_pub_.publish(std_msgs::Empty()); }

private:
  void onInput(const std_msgs::Empty::ConstPtr &) {}

  ros::Publisher alarm_pub_;
  ros::Subscriber input_sub_;
};

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "monitor");
  QCoreApplication app(argc, argv);
  ros::NodeHandle nh;
  Watchdog watchdog;
  Monitor monitor(nh, &watchdog);
  return app.exec();
}
"""


def test_another_classs_timeout_signal_is_no_clock(tmp_path):
    summary = analyze_source(tmp_path, 'monitor', WATCHDOG)
    [node] = summary.nodes
    assert node.timers == []
    [alarm] = node.publishers
    assert (alarm.topic, alarm.label, alarm.pattern) == \
        ('alarm', 'dependent', 'none')
