// colcon-rsia model of <rclcpp/callback_group.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
