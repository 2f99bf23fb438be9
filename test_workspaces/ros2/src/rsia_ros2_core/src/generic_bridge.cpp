// Generic (type-erased) publishers and subscriptions made in main on a node
// from rclcpp::Node::make_shared. The type is a string ("std_msgs/msg/String"),
// which names the message type. Publishers are captured by value in the lambdas.
// - chatter_copy is published from the generic subscription: dependent
// - heartbeat from the 1 s wall timer: independent
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp/serialization.hpp"
#include "std_msgs/msg/empty.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("generic_bridge");

  auto copy_pub = node->create_generic_publisher(
    "chatter_copy", "std_msgs/msg/String", rclcpp::QoS(10));
  auto sub = node->create_generic_subscription(
    "chatter", "std_msgs/msg/String", rclcpp::QoS(10),
    [copy_pub](std::shared_ptr<rclcpp::SerializedMessage> message) {
      copy_pub->publish(*message);
    });

  auto beat_pub = node->create_generic_publisher(
    "heartbeat", "std_msgs/msg/Empty", 1);
  auto timer = node->create_wall_timer(
    std::chrono::seconds(1),
    [beat_pub]() {
      rclcpp::Serialization<std_msgs::msg::Empty> serialization;
      std_msgs::msg::Empty beat;
      rclcpp::SerializedMessage serialized;
      serialization.serialize_message(&beat, &serialized);
      beat_pub->publish(serialized);
    });

  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
