// One-shot inputs: rclcpp::wait_for_message makes a temporary subscription,
// an input of the node like any other; what is published after it follows
// the messages that arrive.
// - calibrated is published in main's loop each time a camera_info arrives
//   (no Rate paces that loop): dependent
// - heartbeat only from the 500 ms timer, whose callback takes an
//   rclcpp::TimerInfo (Rolling): independent (timer, 2 Hz)
// - an rclcpp::ParameterEventHandler the code makes subscribes to
//   /parameter_events (unlike the node's own parameter services); gain is
//   published from its parameter callback: dependent
#include <chrono>
#include <memory>

#include "rclcpp/parameter_event_handler.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp/wait_for_message.hpp"
#include "sensor_msgs/msg/camera_info.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/empty.hpp"
#include "std_msgs/msg/float64.hpp"

using namespace std::chrono_literals;

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("calibration");
  auto calibrated_pub = node->create_publisher<std_msgs::msg::Bool>("calibrated", 1);
  auto heartbeat_pub = node->create_publisher<std_msgs::msg::Empty>("heartbeat", 1);
  auto timer = node->create_wall_timer(
    500ms,
    [heartbeat_pub](const rclcpp::TimerInfo & timer_info) {
      (void)timer_info;
      heartbeat_pub->publish(std_msgs::msg::Empty());
    });

  auto gain_pub = node->create_publisher<std_msgs::msg::Float64>("gain", 1);
  auto parameter_events = std::make_shared<rclcpp::ParameterEventHandler>(node);
  auto gain_callback = parameter_events->add_parameter_callback(
    "gain", [gain_pub](const rclcpp::Parameter & parameter) {
      std_msgs::msg::Float64 gain;
      gain.data = parameter.as_double();
      gain_pub->publish(gain);
    });

  sensor_msgs::msg::CameraInfo camera_info;
  while (rclcpp::ok()) {
    if (rclcpp::wait_for_message(camera_info, node, "camera_info", 5s)) {
      std_msgs::msg::Bool calibrated;
      calibrated.data = camera_info.width > 0;
      calibrated_pub->publish(calibrated);
    }
    rclcpp::spin_some(node);
  }
  rclcpp::shutdown();
  return 0;
}
