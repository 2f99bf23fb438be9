// colcon-rsia model of <controller_interface/controller_interface.hpp>
// (ros2_control): a controller that no other controller chains to.
#ifndef RSIA_MODEL_CONTROLLER_INTERFACE_CONTROLLER_INTERFACE_HPP
#define RSIA_MODEL_CONTROLLER_INTERFACE_CONTROLLER_INTERFACE_HPP

#include <controller_interface/controller_interface_base.hpp>

namespace controller_interface
{

class ControllerInterface : public ControllerInterfaceBase
{
public:
  ControllerInterface();
  virtual ~ControllerInterface() = default;
  bool is_chainable() const final;
  bool set_chained_mode(bool chained_mode) final;
  bool is_in_chained_mode() const final;
};

using ControllerInterfaceSharedPtr = std::shared_ptr<ControllerInterface>;

}  // namespace controller_interface

#endif  // RSIA_MODEL_CONTROLLER_INTERFACE_CONTROLLER_INTERFACE_HPP
