// colcon-rsia model of <rclcpp/utilities.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
