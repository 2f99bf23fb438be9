#include "rsia_ros2_common/graph_listener.hpp"

#include <functional>
#include <string>

namespace rsia_ros2_common
{

GraphListener::GraphListener(rclcpp::Node * node)
{
  announcements_ = node->create_publisher<std_msgs::msg::String>(
    "graph_announcements", 10);
}

void GraphListener::subscribe(rclcpp::Node * node, size_t depth)
{
  updates_ = node->create_subscription<std_msgs::msg::String>(
    "graph_updates", rclcpp::QoS(depth),
    std::bind(&GraphListener::on_update, this, std::placeholders::_1));
}

void GraphListener::announce(const std::string & text)
{
  std_msgs::msg::String message;
  message.data = text;
  announcements_->publish(message);
}

void GraphListener::on_update(const std_msgs::msg::String &)
{
  ++updates_seen_;
}

rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr make_gauge(
  rclcpp::Node * node, const std::string & topic)
{
  return node->create_publisher<std_msgs::msg::Float64>(topic, 10);
}

}  // namespace rsia_ros2_common
