# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Topic names a node's code gives in one unit and uses in another.

A sensor class creates its publisher from a constructor parameter (in
battery.cpp); the node constructs it with a literal (in robot.cpp). The
expectations are written from the two files below.
"""

from colcon_rsia.package import analysis

SENSOR_HPP = """\
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/battery_state.hpp>
class Battery
{
public:
  Battery(rclcpp::Node * node, const std::string & topic_name);
  void publish();
private:
  rclcpp::Publisher<sensor_msgs::msg::BatteryState>::SharedPtr pub_;
};
"""
BATTERY_CPP = """\
#include "robot/battery.hpp"
Battery::Battery(rclcpp::Node * node, const std::string & topic_name)
{
  pub_ = node->create_publisher<sensor_msgs::msg::BatteryState>(
    topic_name, 10);
}
void Battery::publish()
{
  pub_->publish(sensor_msgs::msg::BatteryState());
}
"""
ROBOT_CPP = """\
#include <chrono>
#include "robot/battery.hpp"
using namespace std::chrono_literals;
class Robot : public rclcpp::Node
{
public:
  Robot()
  : Node("robot"), battery_(this, "battery_state")
  {
    timer_ = create_wall_timer(1s, [this]() { battery_.publish(); });
  }
private:
  Battery battery_;
  rclcpp::TimerBase::SharedPtr timer_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Robot>());
}
"""
CMAKE = """cmake_minimum_required(VERSION 3.8)
project(robot)
add_executable(robot_node src/robot.cpp src/battery.cpp)
"""


def test_a_topic_parameter_named_by_the_callers_in_another_unit(tmp_path):
    package = tmp_path / 'robot'
    (package / 'src').mkdir(parents=True)
    (package / 'include' / 'robot').mkdir(parents=True)
    (package / 'include' / 'robot' / 'battery.hpp').write_text(SENSOR_HPP)
    (package / 'src' / 'battery.cpp').write_text(BATTERY_CPP)
    (package / 'src' / 'robot.cpp').write_text(ROBOT_CPP)
    (package / 'CMakeLists.txt').write_text(CMAKE)
    summary = analysis.analyze_package(
        name='robot', path=str(package), build_base=str(tmp_path / 'build'),
        jobs=1, header_mode='model', workspace_package_dirs=[str(package)])
    [node] = summary.nodes
    [publisher] = node.publishers
    # (the node subscribes to nothing: pattern 1)
    assert (publisher.topic, publisher.topic_is_literal, publisher.label,
            publisher.pattern) == ('battery_state', True, 'independent',
                                   'no_subscribers')
