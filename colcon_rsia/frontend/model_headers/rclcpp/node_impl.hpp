// colcon-rsia model of <rclcpp/node_impl.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
