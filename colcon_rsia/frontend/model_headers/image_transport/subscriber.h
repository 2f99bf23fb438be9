// colcon-rsia model of <image_transport/subscriber.h>.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_SUBSCRIBER_H
#define RSIA_MODEL_IMAGE_TRANSPORT_SUBSCRIBER_H

#include <cstdint>
#include <string>

#include <image_transport/transport_hints.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

namespace image_transport
{

class Subscriber
{
public:
  Subscriber();

  std::string getTopic() const;
  uint32_t getNumPublishers() const;
  std::string getTransport() const;
  void shutdown();
  operator void*() const;
  bool operator<(const Subscriber& rhs) const;
  bool operator!=(const Subscriber& rhs) const;
  bool operator==(const Subscriber& rhs) const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_SUBSCRIBER_H
