// colcon-rsia model of <rcl/arguments.h>: its flags are in
// <rclcpp/rclcpp.hpp> (rclcpp includes the C layers)
#include <rclcpp/rclcpp.hpp>
