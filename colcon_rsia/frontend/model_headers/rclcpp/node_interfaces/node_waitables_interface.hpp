// colcon-rsia model of <rclcpp/node_interfaces/node_waitables_interface.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
