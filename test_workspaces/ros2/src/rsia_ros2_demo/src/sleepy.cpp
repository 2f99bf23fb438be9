// a loop paced by std::this_thread::sleep_for in a node that subscribes:
// dependent (a sleep is no adaptive rate)
#include <chrono>
#include <memory>
#include <thread>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

void onCommand(std_msgs::msg::String::ConstSharedPtr msg)
{
  (void)msg;
}

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("sleepy");
  auto pub = node->create_publisher<std_msgs::msg::String>("heartbeat", 1);
  auto sub = node->create_subscription<std_msgs::msg::String>(
    "command", 10, &onCommand);
  while (rclcpp::ok()) {
    std_msgs::msg::String msg;
    pub->publish(msg);
    rclcpp::spin_some(node);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  rclcpp::shutdown();
  return 0;
}
