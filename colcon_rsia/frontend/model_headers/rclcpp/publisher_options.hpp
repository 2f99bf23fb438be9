// colcon-rsia model of <rclcpp/publisher_options.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
