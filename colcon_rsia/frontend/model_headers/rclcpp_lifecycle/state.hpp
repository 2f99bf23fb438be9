// colcon-rsia model of <rclcpp_lifecycle/state.hpp>: in lifecycle_node.hpp
#include <rclcpp_lifecycle/lifecycle_node.hpp>
