// colcon-rsia model of <rclcpp/subscription_base.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
