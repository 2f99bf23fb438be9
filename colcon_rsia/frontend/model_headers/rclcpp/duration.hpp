// colcon-rsia model of <rclcpp/duration.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
