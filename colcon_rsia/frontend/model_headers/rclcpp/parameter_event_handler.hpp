// colcon-rsia model of <rclcpp/parameter_event_handler.hpp>: declared in
// <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
