// colcon-rsia model of <hardware_interface/handle.hpp> (ros2_control): the
// interfaces a controller reads and writes (no ROS communication).
#ifndef RSIA_MODEL_HARDWARE_INTERFACE_HANDLE_HPP
#define RSIA_MODEL_HARDWARE_INTERFACE_HANDLE_HPP

#include <memory>
#include <string>

namespace hardware_interface
{

class Handle
{
public:
  Handle(
    const std::string & prefix_name, const std::string & interface_name,
    double * value_ptr = nullptr);
  const std::string & get_name() const;
  const std::string & get_interface_name() const;
  const std::string & get_prefix_name() const;
  double get_value() const;
  bool set_value(double value);
};

class StateInterface : public Handle
{
public:
  using Handle::Handle;
  using SharedPtr = std::shared_ptr<StateInterface>;
  using ConstSharedPtr = std::shared_ptr<const StateInterface>;
};

class CommandInterface : public Handle
{
public:
  using Handle::Handle;
  using SharedPtr = std::shared_ptr<CommandInterface>;
};

}  // namespace hardware_interface

#endif  // RSIA_MODEL_HARDWARE_INTERFACE_HANDLE_HPP
