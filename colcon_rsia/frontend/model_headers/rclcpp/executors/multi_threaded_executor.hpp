// colcon-rsia model of <rclcpp/executors/multi_threaded_executor.hpp>: declared in <rclcpp/rclcpp.hpp>
#include <rclcpp/rclcpp.hpp>
