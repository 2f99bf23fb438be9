// colcon-rsia model of <rclcpp/parameter_client.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
