// colcon-rsia model of <rclcpp_action/client_goal_handle.hpp>: in rclcpp_action.hpp
#include <rclcpp_action/rclcpp_action.hpp>
