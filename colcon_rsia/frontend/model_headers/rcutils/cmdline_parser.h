// colcon-rsia model of <rcutils/cmdline_parser.h>: the declarations node code uses
// are in <rclcpp/rclcpp.hpp> (rclcpp includes the C layers)
#include <rclcpp/rclcpp.hpp>
