// colcon-rsia model of <image_transport/single_subscriber_publisher.h>.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_SINGLE_SUBSCRIBER_PUBLISHER_H
#define RSIA_MODEL_IMAGE_TRANSPORT_SINGLE_SUBSCRIBER_PUBLISHER_H

#include <cstdint>
#include <string>

#include <boost/function.hpp>
#include <boost/noncopyable.hpp>
#include <sensor_msgs/Image.h>

namespace image_transport
{

class SingleSubscriberPublisher : boost::noncopyable
{
public:
  typedef boost::function<uint32_t()> GetNumSubscribersFn;
  typedef boost::function<void(const sensor_msgs::Image&)> PublishFn;

  SingleSubscriberPublisher(const std::string& caller_id, const std::string& topic,
                            const GetNumSubscribersFn& num_subscribers_fn,
                            const PublishFn& publish_fn);

  std::string getSubscriberName() const;
  std::string getTopic() const;
  uint32_t getNumSubscribers() const;
  void publish(const sensor_msgs::Image& message) const;
  void publish(const sensor_msgs::ImageConstPtr& message) const;
};

typedef boost::function<void(const SingleSubscriberPublisher&)> SubscriberStatusCallback;

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_SINGLE_SUBSCRIBER_PUBLISHER_H
