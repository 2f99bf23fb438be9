// colcon-rsia model of <rclcpp_action/types.hpp>: in rclcpp_action.hpp
#include <rclcpp_action/rclcpp_action.hpp>
