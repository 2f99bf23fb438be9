// colcon-rsia model of <rclcpp/visibility_control.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
