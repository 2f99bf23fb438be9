// colcon-rsia model of <rclcpp/create_publisher.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
