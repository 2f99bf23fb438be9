// The odometry is published from update() through a helper: the controller
// manager's loop paces it (host_periodic), whatever rate the commands come
// at. Each command is echoed from its callback: that edge follows the
// commands.
#include "rsia_ros2_plugins/odometry_controller.hpp"

#include <functional>

#include "pluginlib/class_list_macros.hpp"

namespace rsia_ros2_plugins
{

controller_interface::CallbackReturn OdometryController::on_init()
{
  return controller_interface::CallbackReturn::SUCCESS;
}

controller_interface::InterfaceConfiguration
OdometryController::command_interface_configuration() const
{
  return {controller_interface::interface_configuration_type::NONE, {}};
}

controller_interface::InterfaceConfiguration
OdometryController::state_interface_configuration() const
{
  return {controller_interface::interface_configuration_type::NONE, {}};
}

controller_interface::CallbackReturn OdometryController::on_configure(
  const rclcpp_lifecycle::State &)
{
  odom_pub_ = get_node()->create_publisher<nav_msgs::msg::Odometry>("~/odom", 10);
  command_echo_pub_ = get_node()->create_publisher<geometry_msgs::msg::Twist>(
    "~/command_echo", 10);
  command_sub_ = get_node()->create_subscription<geometry_msgs::msg::Twist>(
    "~/cmd_vel", 10,
    std::bind(&OdometryController::on_command, this, std::placeholders::_1));
  return controller_interface::CallbackReturn::SUCCESS;
}

void OdometryController::on_command(const geometry_msgs::msg::Twist::SharedPtr msg)
{
  last_command_ = *msg;
  command_echo_pub_->publish(*msg);
}

controller_interface::return_type OdometryController::update(
  const rclcpp::Time & time, const rclcpp::Duration & period)
{
  x_ += last_command_.linear.x * period.seconds();
  publish_odometry(time);
  return controller_interface::return_type::OK;
}

void OdometryController::publish_odometry(const rclcpp::Time & time)
{
  nav_msgs::msg::Odometry odom;
  odom.header.stamp = time;
  odom.pose.pose.position.x = x_;
  odom_pub_->publish(odom);
}

}  // namespace rsia_ros2_plugins

PLUGINLIB_EXPORT_CLASS(
  rsia_ros2_plugins::OdometryController, controller_interface::ControllerInterface)
