// colcon-rsia model of <rclcpp/parameter_value.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
