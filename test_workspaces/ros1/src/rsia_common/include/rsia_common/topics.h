// Wrappers the nodes of other packages make their endpoints through. The
// analysis reads their bodies at each call site: which parameter is the
// topic, whether the template argument is the message type, which
// parameter is the callback, whether a method publishes.
#ifndef RSIA_COMMON_TOPICS_H
#define RSIA_COMMON_TOPICS_H

#include <string>

#include <boost/shared_ptr.hpp>
#include <ros/ros.h>
#include <std_msgs/Empty.h>

namespace rsia_common
{

template <typename M>
ros::Publisher advertiseLatched(ros::NodeHandle& nh, const std::string& topic)
{
  return nh.advertise<M>(topic, 1, true);
}

template <typename M, typename T>
ros::Subscriber subscribeTo(ros::NodeHandle& nh, const std::string& topic,
                            void (T::*callback)(const boost::shared_ptr<M const>&), T* object)
{
  return nh.subscribe(topic, 10, callback, object);
}

// the constructor advertises; beat() publishes through that publisher
class Heartbeat
{
public:
  Heartbeat(ros::NodeHandle& nh, const std::string& topic)
    : publisher_(nh.advertise<std_msgs::Empty>(topic, 1))
  {
  }

  void beat()
  {
    publisher_.publish(std_msgs::Empty());
  }

private:
  ros::Publisher publisher_;
};

}  // namespace rsia_common

#endif  // RSIA_COMMON_TOPICS_H
