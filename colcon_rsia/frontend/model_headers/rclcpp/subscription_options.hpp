// colcon-rsia model of <rclcpp/subscription_options.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
