// colcon-rsia model of <rmw/types.h>: the declarations node code uses
// are in <rclcpp/rclcpp.hpp> (rclcpp includes the C layers)
#include <rclcpp/rclcpp.hpp>
