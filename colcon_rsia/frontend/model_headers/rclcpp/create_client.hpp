// colcon-rsia model of <rclcpp/create_client.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
