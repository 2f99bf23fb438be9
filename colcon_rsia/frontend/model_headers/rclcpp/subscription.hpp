// colcon-rsia model of <rclcpp/subscription.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
