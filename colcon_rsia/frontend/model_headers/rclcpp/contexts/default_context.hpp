// colcon-rsia model of <rclcpp/contexts/default_context.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
