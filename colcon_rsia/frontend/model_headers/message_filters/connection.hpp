// colcon-rsia model of <message_filters/connection.hpp> (ROS 2; Humble's
// <message_filters/connection.h> includes it when rclcpp came first).
#ifndef RSIA_MODEL_MESSAGE_FILTERS_CONNECTION
#define RSIA_MODEL_MESSAGE_FILTERS_CONNECTION

#include <functional>

namespace message_filters
{

class Connection
{
public:
  using VoidDisconnectFunction = std::function<void (void)>;
  using WithConnectionDisconnectFunction = std::function<void (const Connection &)>;

  Connection();
  Connection(const VoidDisconnectFunction & func);
  void disconnect();
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_CONNECTION
