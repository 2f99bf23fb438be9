// A component that the package also wraps in an executable of its own
// (src/lidar_main.cpp): one node, whichever way it is started.
#ifndef RSIA_ROS2_DEMO__LIDAR_COMPONENT_HPP_
#define RSIA_ROS2_DEMO__LIDAR_COMPONENT_HPP_

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"

namespace rsia_demo
{

class LidarComponent : public rclcpp::Node
{
public:
  explicit LidarComponent(const rclcpp::NodeOptions & options);

private:
  void sweep();

  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr scan_pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

}  // namespace rsia_demo

#endif  // RSIA_ROS2_DEMO__LIDAR_COMPONENT_HPP_
