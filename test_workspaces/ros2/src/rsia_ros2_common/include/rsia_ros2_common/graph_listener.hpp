// Helpers compiled into the package's library: their bodies are in
// src/graph_listener.cpp, out of sight of the other packages' units, so
// the analysis of this package exports their summaries (wrappers.json) and
// the packages analysed after it read them at their call sites.
#ifndef RSIA_ROS2_COMMON__GRAPH_LISTENER_HPP_
#define RSIA_ROS2_COMMON__GRAPH_LISTENER_HPP_

#include <string>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/float64.hpp"
#include "std_msgs/msg/string.hpp"

namespace rsia_ros2_common
{

// the constructor makes the announcement publisher, announce() publishes
// through it, subscribe() listens to the graph updates with its own callback
class GraphListener
{
public:
  explicit GraphListener(rclcpp::Node * node);
  void subscribe(rclcpp::Node * node, size_t depth);
  void announce(const std::string & text);

private:
  void on_update(const std_msgs::msg::String & message);

  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr announcements_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr updates_;
  size_t updates_seen_ = 0;
};

// a publisher on the topic the caller names
rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr make_gauge(
  rclcpp::Node * node, const std::string & topic);

}  // namespace rsia_ros2_common

#endif  // RSIA_ROS2_COMMON__GRAPH_LISTENER_HPP_
