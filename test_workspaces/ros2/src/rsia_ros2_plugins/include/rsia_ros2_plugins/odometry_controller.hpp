// A ros2_control controller: the controller manager calls update() from its
// fixed-rate loop; velocity commands arrive on a subscription made in
// on_configure.
#ifndef RSIA_ROS2_PLUGINS__ODOMETRY_CONTROLLER_HPP_
#define RSIA_ROS2_PLUGINS__ODOMETRY_CONTROLLER_HPP_

#include <memory>

#include "controller_interface/controller_interface.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/state.hpp"

namespace rsia_ros2_plugins
{

class OdometryController : public controller_interface::ControllerInterface
{
public:
  controller_interface::CallbackReturn on_init() override;
  controller_interface::InterfaceConfiguration command_interface_configuration() const override;
  controller_interface::InterfaceConfiguration state_interface_configuration() const override;
  controller_interface::CallbackReturn on_configure(
    const rclcpp_lifecycle::State & previous_state) override;
  controller_interface::return_type update(
    const rclcpp::Time & time, const rclcpp::Duration & period) override;

private:
  void on_command(const geometry_msgs::msg::Twist::SharedPtr msg);
  void publish_odometry(const rclcpp::Time & time);

  double x_ = 0.0;
  geometry_msgs::msg::Twist last_command_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr command_sub_;
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr odom_pub_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr command_echo_pub_;
};

}  // namespace rsia_ros2_plugins

#endif  // RSIA_ROS2_PLUGINS__ODOMETRY_CONTROLLER_HPP_
