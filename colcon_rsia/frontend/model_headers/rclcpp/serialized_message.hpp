// colcon-rsia model of <rclcpp/serialized_message.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
