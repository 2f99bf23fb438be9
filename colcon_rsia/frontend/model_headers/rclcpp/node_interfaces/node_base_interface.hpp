// colcon-rsia model of <rclcpp/node_interfaces/node_base_interface.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
