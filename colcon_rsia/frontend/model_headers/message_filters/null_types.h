// colcon-rsia model of <message_filters/null_types.h>.
//
// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
// The ROS 2 class is in <message_filters/null_types.hpp>; both define
// RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES.
#ifdef RSIA_MODEL_RCLCPP
#include <message_filters/null_types.hpp>
#else  // ROS 1
#ifndef RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES
#define RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <message_filters/connection.h>
#include <ros/message_event.h>

namespace message_filters
{

struct NullType
{
};
typedef boost::shared_ptr<NullType const> NullTypeConstPtr;

template <class M>
struct NullFilter
{
  template <typename C>
  Connection registerCallback(const C&);
  template <typename P>
  Connection registerCallback(const boost::function<void(P)>&);
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES
#endif  // RSIA_MODEL_RCLCPP
