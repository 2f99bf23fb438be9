// colcon-rsia model of <rclcpp/init_options.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
