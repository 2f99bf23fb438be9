# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""ROS 2 lazy subscription: made in a publisher's matched callback.

The publisher's options hold ``event_callbacks.matched_callback``, which
rclcpp runs when a subscription matches the publisher or leaves it; the
node subscribes to its input there, and publishes in that subscription's
callback. The subscription is the node's, and the publisher depends on
it (without the callback, the node would seem to subscribe to nothing and
its publisher would be independent). A component: only what its class's
methods reach, and the callbacks they register, is the node's code.
Expectations written by hand from the code below.
"""

from conftest import analyze_source

RECTIFY = r"""
#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "std_msgs/msg/string.hpp"

class Rectify : public rclcpp::Node
{
public:
  explicit Rectify(const rclcpp::NodeOptions & options)
  : rclcpp::Node("rectify", options)
  {
    rclcpp::PublisherOptions lazy;
    lazy.event_callbacks.matched_callback =
      [this](rclcpp::MatchedInfo & info)
      {
        if (info.current_count == 0) {
          input_.reset();
        } else if (!input_) {
          input_ = create_subscription<sensor_msgs::msg::Image>(
            "image", 1, [this](sensor_msgs::msg::Image::ConstSharedPtr m) {
              rectified_->publish(*m);
            });
        }
      };
    rectified_ = create_publisher<sensor_msgs::msg::Image>(
      "image_rect", 1, lazy);
    status_ = create_publisher<std_msgs::msg::String>("status", 1);
    timer_ = create_wall_timer(std::chrono::seconds(1), [this]() {
      status_->publish(std_msgs::msg::String());
    });
  }

private:
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr input_;
  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr rectified_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_;
  rclcpp::TimerBase::SharedPtr timer_;
};

#include "rclcpp_components/register_node_macro.hpp"
RCLCPP_COMPONENTS_REGISTER_NODE(Rectify)
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.8)
project(rectify)
find_package(rclcpp_components REQUIRED)
add_library(rectify SHARED src/rectify.cpp)
rclcpp_components_register_node(rectify PLUGIN "Rectify" EXECUTABLE rectify_node)
"""


def test_a_subscription_made_when_a_subscriber_matches_is_the_nodes(
        tmp_path):
    summary = analyze_source(tmp_path, 'rectify', RECTIFY, cmake=CMAKE)
    [node] = summary.nodes
    assert [(s.topic, s.location) for s in node.subscribers] == [
        ('image', 'src/rectify.cpp:20')]
    labels = {p.topic: (p.label, sorted(t.name for t in p.triggers or []))
              for p in node.publishers}
    assert labels == {
        'image_rect': ('dependent', ['image']),
        'status': ('independent', []),
    }
    # the matched callback is a root of the node, at the publisher it
    # belongs to
    connect = [r for r in node.roots if r.kind == 'connect']
    assert [r.location for r in connect] == ['src/rectify.cpp:26']
