// colcon-rsia model of <rclcpp/node_options.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
