// colcon-rsia model of <rclcpp/node_interfaces/get_node_timers_interface.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
