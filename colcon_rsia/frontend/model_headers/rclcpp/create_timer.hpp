// colcon-rsia model of <rclcpp/create_timer.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
