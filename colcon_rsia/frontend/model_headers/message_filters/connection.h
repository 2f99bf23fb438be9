// colcon-rsia model of <message_filters/connection.h>.
//
// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
// The ROS 2 class is in <message_filters/connection.hpp>; both define
// RSIA_MODEL_MESSAGE_FILTERS_CONNECTION.
#ifdef RSIA_MODEL_RCLCPP
#include <message_filters/connection.hpp>
#else  // ROS 1
#ifndef RSIA_MODEL_MESSAGE_FILTERS_CONNECTION
#define RSIA_MODEL_MESSAGE_FILTERS_CONNECTION

#include <boost/function.hpp>

namespace message_filters
{

class Connection
{
public:
  typedef boost::function<void(void)> VoidDisconnectFunction;
  typedef boost::function<void(const Connection&)> WithConnectionDisconnectFunction;

  Connection();
  Connection(const VoidDisconnectFunction& func);
  void disconnect();
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_CONNECTION
#endif  // RSIA_MODEL_RCLCPP
