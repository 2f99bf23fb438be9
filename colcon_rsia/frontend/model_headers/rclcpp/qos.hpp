// colcon-rsia model of <rclcpp/qos.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
