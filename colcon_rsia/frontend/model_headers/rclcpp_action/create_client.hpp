// colcon-rsia model of <rclcpp_action/create_client.hpp>: in rclcpp_action.hpp
#include <rclcpp_action/rclcpp_action.hpp>
