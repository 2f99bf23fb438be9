// colcon-rsia model of <message_filters/simple_filter.hpp> (ROS 2): the base
// of message_filters::Subscriber (and of image_transport::SubscriberFilter,
// tf2_ros::MessageFilter) with registerCallback.
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER
#define RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER

#include <functional>
#include <memory>
#include <string>

#include <message_filters/connection.hpp>
#include <message_filters/message_event.hpp>

namespace message_filters
{

class noncopyable
{
protected:
  noncopyable();
  ~noncopyable();
  noncopyable(const noncopyable &) = delete;
  noncopyable & operator=(const noncopyable &) = delete;
};

template<class M>
class SimpleFilter : public noncopyable
{
public:
  using MConstPtr = std::shared_ptr<M const>;
  using Callback = std::function<void (const MConstPtr &)>;
  using EventType = MessageEvent<M const>;
  using EventCallback = std::function<void (const EventType &)>;

  template<typename C>
  Connection registerCallback(const C & callback);
  template<typename P>
  Connection registerCallback(const std::function<void(P)> & callback);
  template<typename P>
  Connection registerCallback(void (*callback)(P));
  template<typename T, typename P>
  Connection registerCallback(void (T::* callback)(P), T * t);

  void setName(const std::string & name);
  const std::string & getName();

protected:
  void signalMessage(const MConstPtr & msg);
  void signalMessage(const EventType & event);
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SIMPLE_FILTER
