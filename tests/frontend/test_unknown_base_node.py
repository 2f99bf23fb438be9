# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A node class whose base comes from a library the machine lacks.

Inside its methods, ``create_publisher<M>(...)`` and
``create_wall_timer(...)`` are the unknown base's members; the parse
finds no declaration of them, and the repairs declare catch-all functions
of those names. A call of such a catch-all is known by its name alone.
Expectations written by hand from the code below.
"""

from conftest import analyze_source

PLANNER = r"""
#include <chrono>
#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "nav_msgs/msg/path.hpp"
#include "route_lib/managed_node.hpp"

using namespace std::chrono_literals;

class Planner : public route_lib::ManagedNode
{
public:
  Planner() : route_lib::ManagedNode("planner_server")
  {
    plan_publisher_ = create_publisher<nav_msgs::msg::Path>("plan", 1);
    timer_ = create_wall_timer(250ms, [this]() { publishPlan(); });
  }

private:
  void publishPlan()
  {
    nav_msgs::msg::Path path;
    plan_publisher_->publish(path);
  }
  rclcpp::Publisher<nav_msgs::msg::Path>::SharedPtr plan_publisher_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Planner>()->get_node_base_interface());
  return 0;
}
"""


def test_calls_of_an_unknown_bases_members_are_known_by_name(tmp_path):
    summary = analyze_source(tmp_path, 'planner', PLANNER,
                             repair='when-it-pays')
    [node] = summary.nodes
    # published from the 250 ms timer the constructor makes
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('plan', 'independent')]
    [timer] = node.timers
    assert timer.rate_hz == 4.0
    # the unknown base's constructor takes a string: by convention the
    # node's name, but nothing the analysis knows says so
    assert node.name is None
