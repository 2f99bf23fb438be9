// colcon-rsia model of <rclcpp/serialization.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
