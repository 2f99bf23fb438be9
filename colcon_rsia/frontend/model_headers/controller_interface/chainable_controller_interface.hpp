// colcon-rsia model of <controller_interface/chainable_controller_interface.hpp>
// (ros2_control): update() is final and calls the two methods below.
#ifndef RSIA_MODEL_CONTROLLER_INTERFACE_CHAINABLE_CONTROLLER_INTERFACE_HPP
#define RSIA_MODEL_CONTROLLER_INTERFACE_CHAINABLE_CONTROLLER_INTERFACE_HPP

#include <controller_interface/controller_interface_base.hpp>

namespace controller_interface
{

class ChainableControllerInterface : public ControllerInterfaceBase
{
public:
  ChainableControllerInterface();
  virtual ~ChainableControllerInterface() = default;
  return_type update(
    const rclcpp::Time & time, const rclcpp::Duration & period) final;
  bool is_chainable() const final;
  bool set_chained_mode(bool chained_mode) final;
  bool is_in_chained_mode() const final;

protected:
  virtual std::vector<hardware_interface::StateInterface>
  on_export_state_interfaces();
  virtual std::vector<hardware_interface::CommandInterface>
  on_export_reference_interfaces();
  virtual bool on_set_chained_mode(bool chained_mode);
  virtual return_type update_reference_from_subscribers(
    const rclcpp::Time & time, const rclcpp::Duration & period) = 0;
  virtual return_type update_and_write_commands(
    const rclcpp::Time & time, const rclcpp::Duration & period) = 0;

  std::vector<double> reference_interfaces_;
  std::vector<double> state_interfaces_values_;
};

}  // namespace controller_interface

#endif  // RSIA_MODEL_CONTROLLER_INTERFACE_CHAINABLE_CONTROLLER_INTERFACE_HPP
