// colcon-rsia model of <rclcpp/publisher.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
