// The lidar component as a plain executable: main only instantiates it.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rsia_ros2_demo/lidar_component.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<rsia_demo::LidarComponent>(rclcpp::NodeOptions()));
  rclcpp::shutdown();
  return 0;
}
