// colcon-rsia model of <rclcpp/create_generic_publisher.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
