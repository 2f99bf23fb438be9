// colcon-rsia model of <ros/single_subscriber_publisher.h>: the parameter of
// advertise's connect/disconnect callbacks.
#ifndef RSIA_MODEL_ROS_SINGLE_SUBSCRIBER_PUBLISHER_H
#define RSIA_MODEL_ROS_SINGLE_SUBSCRIBER_PUBLISHER_H

#include <string>

#include <boost/shared_ptr.hpp>
#include <ros/forwards.h>

namespace ros
{

class SingleSubscriberPublisher
{
public:
  SingleSubscriberPublisher(const SingleSubscriberPublisher&) = delete;
  SingleSubscriberPublisher& operator=(const SingleSubscriberPublisher&) = delete;
  ~SingleSubscriberPublisher();

  template <class M>
  void publish(const boost::shared_ptr<M const>& message) const;
  template <class M>
  void publish(const M& message) const;

  std::string getTopic() const;
  std::string getSubscriberName() const;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_SINGLE_SUBSCRIBER_PUBLISHER_H
