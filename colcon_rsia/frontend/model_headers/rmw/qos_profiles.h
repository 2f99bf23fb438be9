// colcon-rsia model of <rmw/qos_profiles.h>: the declarations node code uses
// are in <rclcpp/rclcpp.hpp> (rclcpp includes the C layers)
#include <rclcpp/rclcpp.hpp>
