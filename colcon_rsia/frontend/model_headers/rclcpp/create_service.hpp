// colcon-rsia model of <rclcpp/create_service.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
