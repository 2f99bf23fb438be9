// A broadcaster with no inputs at all: its joint states are independent
// because nothing drives it but the controller manager (no_subscribers).
// It is exported in code only (missing from controllers.xml): it still loads,
// and is named after its class.
#include <memory>

#include "controller_interface/controller_interface.hpp"
#include "pluginlib/class_list_macros.hpp"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/joint_state.hpp"

namespace rsia_ros2_plugins
{

class StateBroadcaster : public controller_interface::ControllerInterface
{
public:
  controller_interface::CallbackReturn on_init() override
  {
    return controller_interface::CallbackReturn::SUCCESS;
  }

  controller_interface::InterfaceConfiguration command_interface_configuration() const override
  {
    return {controller_interface::interface_configuration_type::NONE, {}};
  }

  controller_interface::InterfaceConfiguration state_interface_configuration() const override
  {
    return {controller_interface::interface_configuration_type::ALL, {}};
  }

  controller_interface::CallbackReturn on_activate(const rclcpp_lifecycle::State &) override
  {
    state_pub_ = get_node()->create_publisher<sensor_msgs::msg::JointState>(
      "joint_states", rclcpp::SystemDefaultsQoS());
    return controller_interface::CallbackReturn::SUCCESS;
  }

  controller_interface::return_type update(
    const rclcpp::Time & time, const rclcpp::Duration &) override
  {
    sensor_msgs::msg::JointState state;
    state.header.stamp = time;
    state_pub_->publish(state);
    return controller_interface::return_type::OK;
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::JointState>::SharedPtr state_pub_;
};

}  // namespace rsia_ros2_plugins

PLUGINLIB_EXPORT_CLASS(
  rsia_ros2_plugins::StateBroadcaster, controller_interface::ControllerInterface)
