// colcon-rsia model of <rcl/types.h>: the declarations node code uses
// are in <rclcpp/rclcpp.hpp> (rclcpp includes the C layers)
#include <rclcpp/rclcpp.hpp>
