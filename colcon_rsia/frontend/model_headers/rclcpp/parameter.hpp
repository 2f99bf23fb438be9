// colcon-rsia model of <rclcpp/parameter.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
