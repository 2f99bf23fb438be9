// colcon-rsia model of <hardware_interface/loaned_state_interface.hpp>.
#ifndef RSIA_MODEL_HARDWARE_INTERFACE_LOANED_STATE_INTERFACE_HPP
#define RSIA_MODEL_HARDWARE_INTERFACE_LOANED_STATE_INTERFACE_HPP

#include <optional>
#include <string>

#include <hardware_interface/handle.hpp>

namespace hardware_interface
{

class LoanedStateInterface
{
public:
  explicit LoanedStateInterface(const StateInterface & state_interface);
  const std::string get_name() const;
  const std::string & get_interface_name() const;
  const std::string & get_prefix_name() const;
  double get_value() const;
  template<typename T = double>
  std::optional<T> get_optional() const;
};

}  // namespace hardware_interface

#endif  // RSIA_MODEL_HARDWARE_INTERFACE_LOANED_STATE_INTERFACE_HPP
