// colcon-rsia model of <rclcpp/loaned_message.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
