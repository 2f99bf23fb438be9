// colcon-rsia model of <rclcpp/message_info.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
