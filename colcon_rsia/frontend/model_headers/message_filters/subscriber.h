// colcon-rsia model of <message_filters/subscriber.h>: a subscriber whose topic
// is its constructor's (or subscribe's) second argument.
//
// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
// The ROS 2 class is in <message_filters/subscriber.hpp>; both define
// RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER.
#ifdef RSIA_MODEL_RCLCPP
#include <message_filters/subscriber.hpp>
#else  // ROS 1
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER
#define RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER

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

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER
#endif  // RSIA_MODEL_RCLCPP
