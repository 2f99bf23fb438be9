// colcon-rsia model of <rclcpp/wait_for_message.hpp>: declared in
// <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
