// colcon-rsia model of <message_filters/subscriber.h>: a subscriber whose topic
// is its constructor's (or subscribe's) second argument.
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER_H
#define RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER_H

#include <cstdint>
#include <string>

#include <boost/thread/mutex.hpp>
#include <message_filters/connection.h>
#include <message_filters/simple_filter.h>
#include <ros/ros.h>

namespace message_filters
{

class SubscriberBase
{
public:
  virtual ~SubscriberBase();
  virtual void subscribe(ros::NodeHandle& nh, const std::string& topic, uint32_t queue_size,
                         const ros::TransportHints& transport_hints = ros::TransportHints(),
                         ros::CallbackQueueInterface* callback_queue = 0) = 0;
  virtual void subscribe() = 0;
  virtual void unsubscribe() = 0;
};
typedef boost::shared_ptr<SubscriberBase> SubscriberBasePtr;

template <class M>
class Subscriber : public SubscriberBase, public SimpleFilter<M>
{
public:
  typedef boost::shared_ptr<M const> MConstPtr;
  typedef ros::MessageEvent<M const> EventType;

  Subscriber(ros::NodeHandle& nh, const std::string& topic, uint32_t queue_size,
             const ros::TransportHints& transport_hints = ros::TransportHints(),
             ros::CallbackQueueInterface* callback_queue = 0);
  Subscriber();
  ~Subscriber();

  void subscribe(ros::NodeHandle& nh, const std::string& topic, uint32_t queue_size,
                 const ros::TransportHints& transport_hints = ros::TransportHints(),
                 ros::CallbackQueueInterface* callback_queue = 0);
  void subscribe();
  void unsubscribe();
  std::string getTopic() const;
  const ros::Subscriber& getSubscriber() const;
  template <typename F>
  void connectInput(F& f);
  void add(const EventType& e);
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER_H
