// colcon-rsia model of <rclcpp_action/client.hpp>: in rclcpp_action.hpp
#include <rclcpp_action/rclcpp_action.hpp>
