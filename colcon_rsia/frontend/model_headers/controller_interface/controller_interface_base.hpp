// colcon-rsia model of <controller_interface/controller_interface_base.hpp>
// (ros2_control): written from the documented interface of a controller
// (the ros2_control API documentation). The controller manager loads a
// controller with pluginlib and calls update() from its fixed-rate loop;
// the analysis reads that from colcon_rsia/package/plugin_hosts.py.
#ifndef RSIA_MODEL_CONTROLLER_INTERFACE_CONTROLLER_INTERFACE_BASE_HPP
#define RSIA_MODEL_CONTROLLER_INTERFACE_CONTROLLER_INTERFACE_BASE_HPP

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <hardware_interface/loaned_command_interface.hpp>
#include <hardware_interface/loaned_state_interface.hpp>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>

namespace controller_interface
{

enum class return_type : std::uint8_t { OK = 0, ERROR = 1 };

enum class interface_configuration_type : std::uint8_t
{
  ALL = 0, INDIVIDUAL = 1, NONE = 2, INDIVIDUAL_BEST_EFFORT = 3, REGEX = 4
};

struct InterfaceConfiguration
{
  interface_configuration_type type;
  std::vector<std::string> names = {};
};

using CallbackReturn =
  rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

class ControllerInterfaceBase
  : public rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface
{
public:
  ControllerInterfaceBase();
  virtual ~ControllerInterfaceBase();

  virtual InterfaceConfiguration command_interface_configuration() const = 0;
  virtual InterfaceConfiguration state_interface_configuration() const = 0;
  virtual void assign_interfaces(
    std::vector<hardware_interface::LoanedCommandInterface> && command_interfaces,
    std::vector<hardware_interface::LoanedStateInterface> && state_interfaces);
  virtual void release_interfaces();

  virtual CallbackReturn on_init() = 0;
  virtual return_type update(
    const rclcpp::Time & time, const rclcpp::Duration & period) = 0;

  std::shared_ptr<rclcpp_lifecycle::LifecycleNode> get_node();
  std::shared_ptr<const rclcpp_lifecycle::LifecycleNode> get_node() const;
  const rclcpp_lifecycle::State & get_lifecycle_state() const;
  unsigned int get_update_rate() const;
  bool is_async() const;
  const std::string & get_robot_description() const;

  template<typename ParameterT>
  ParameterT auto_declare(
    const std::string & name, const ParameterT & default_value);

  virtual bool is_chainable() const = 0;
  virtual bool set_chained_mode(bool chained_mode) = 0;
  virtual bool is_in_chained_mode() const = 0;

protected:
  std::vector<hardware_interface::LoanedCommandInterface> command_interfaces_;
  std::vector<hardware_interface::LoanedStateInterface> state_interfaces_;
};

}  // namespace controller_interface

#endif  // RSIA_MODEL_CONTROLLER_INTERFACE_CONTROLLER_INTERFACE_BASE_HPP
