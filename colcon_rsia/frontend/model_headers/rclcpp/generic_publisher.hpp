// colcon-rsia model of <rclcpp/generic_publisher.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
