// colcon-rsia model of <rclcpp/expand_topic_or_service_name.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
