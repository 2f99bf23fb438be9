// colcon-rsia model of <rclcpp/publisher_base.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
