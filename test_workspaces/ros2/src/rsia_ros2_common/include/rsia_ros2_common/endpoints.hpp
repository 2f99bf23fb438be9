// Wrappers the nodes of other packages create their endpoints through: the
// analysis summarises each one (topic from which parameter, message type
// from the template argument, callback from which parameter) and gives the
// fact to every call site, with the caller's own arguments.
#ifndef RSIA_ROS2_COMMON__ENDPOINTS_HPP_
#define RSIA_ROS2_COMMON__ENDPOINTS_HPP_

#include <map>
#include <memory>
#include <string>
#include <utility>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace rsia_ros2_common
{

template<typename MessageT>
typename rclcpp::Publisher<MessageT>::SharedPtr make_publisher(
  rclcpp::Node * node, const std::string & topic)
{
  return node->create_publisher<MessageT>(topic, rclcpp::QoS(10));
}

template<typename MessageT, typename CallbackT>
typename rclcpp::Subscription<MessageT>::SharedPtr make_subscription(
  rclcpp::Node * node, const std::string & topic, CallbackT && callback)
{
  return node->create_subscription<MessageT>(
    topic, rclcpp::SensorDataQoS(), std::forward<CallbackT>(callback));
}

// a wrapper of a wrapper: the topic and the message type are written here
inline rclcpp::Publisher<std_msgs::msg::String>::SharedPtr make_mode_publisher(
  rclcpp::Node * node)
{
  return make_publisher<std_msgs::msg::String>(node, "relay_mode");
}

// a helper object: the publisher is made by the constructor, published
// through by report()
class StatusReporter
{
public:
  StatusReporter(rclcpp::Node * node, const std::string & topic)
  : publisher_(node->create_publisher<std_msgs::msg::String>(topic, 10))
  {
  }

  void report(const std::string & text)
  {
    std_msgs::msg::String message;
    message.data = text;
    publisher_->publish(message);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr publisher_;
};

// makes a publisher on first use and publishes at once
class DebugPublisher
{
public:
  explicit DebugPublisher(rclcpp::Node * node)
  : node_(node)
  {
  }

  template<typename T>
  void publish(const std::string & name, const T & data)
  {
    if (publishers_.count(name) == 0) {
      publishers_[name] = node_->create_publisher<T>(name, 1);
    }
    std::dynamic_pointer_cast<rclcpp::Publisher<T>>(publishers_.at(name))->publish(data);
  }

private:
  rclcpp::Node * node_;
  std::map<std::string, std::shared_ptr<rclcpp::PublisherBase>> publishers_;
};

}  // namespace rsia_ros2_common

#endif  // RSIA_ROS2_COMMON__ENDPOINTS_HPP_
