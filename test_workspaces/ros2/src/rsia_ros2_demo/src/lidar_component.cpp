// A lidar sweeping at 25 Hz (a 40 ms wall timer), registered as a
// component in the source; src/lidar_main.cpp also runs it as an executable.
#include "rsia_ros2_demo/lidar_component.hpp"

#include <chrono>

#include "rclcpp_components/register_node_macro.hpp"

namespace rsia_demo
{

LidarComponent::LidarComponent(const rclcpp::NodeOptions & options)
: Node("lidar", options)
{
  scan_pub_ = create_publisher<sensor_msgs::msg::LaserScan>("scan", 10);
  timer_ = create_wall_timer(std::chrono::milliseconds(40), [this]() {sweep();});
}

void LidarComponent::sweep()
{
  scan_pub_->publish(sensor_msgs::msg::LaserScan());
}

}  // namespace rsia_demo

RCLCPP_COMPONENTS_REGISTER_NODE(rsia_demo::LidarComponent)
