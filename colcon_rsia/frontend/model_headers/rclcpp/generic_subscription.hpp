// colcon-rsia model of <rclcpp/generic_subscription.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
