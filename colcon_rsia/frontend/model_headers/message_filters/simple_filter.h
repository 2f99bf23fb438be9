// colcon-rsia model of <message_filters/simple_filter.h>: the base of
// message_filters::Subscriber (and tf message filters) with registerCallback.
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER_H
#define RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER_H

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

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER_H
