// colcon-rsia model of <message_filters/simple_filter.h>: the base of
// message_filters::Subscriber (and tf message filters) with registerCallback.
//
// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
// The ROS 2 class is in <message_filters/simple_filter.hpp>; both define
// RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER.
#ifdef RSIA_MODEL_RCLCPP
#include <message_filters/simple_filter.hpp>
#else  // ROS 1
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER
#define RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER

#include <string>

#include <boost/bind/bind.hpp>
#include <boost/function.hpp>
#include <boost/noncopyable.hpp>
#include <boost/shared_ptr.hpp>
#include <message_filters/connection.h>
#include <ros/message_event.h>

namespace message_filters
{

template <class M>
class SimpleFilter : public boost::noncopyable
{
public:
  typedef boost::shared_ptr<M const> MConstPtr;
  typedef boost::function<void(const MConstPtr&)> Callback;
  typedef ros::MessageEvent<M const> EventType;
  typedef boost::function<void(const EventType&)> EventCallback;

  template <typename C>
  Connection registerCallback(const C& callback);
  template <typename P>
  Connection registerCallback(const boost::function<void(P)>& callback);
  template <typename P>
  Connection registerCallback(void (*callback)(P));
  template <typename T, typename P>
  Connection registerCallback(void (T::*callback)(P), T* t);

  void setName(const std::string& name);
  const std::string& getName();

protected:
  void signalMessage(const MConstPtr& msg);
  void signalMessage(const ros::MessageEvent<M const>& event);
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER
#endif  // RSIA_MODEL_RCLCPP
