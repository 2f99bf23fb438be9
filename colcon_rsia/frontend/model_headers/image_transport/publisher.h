// colcon-rsia model of <image_transport/publisher.h>: image_transport::Publisher
// and its publish site.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_PUBLISHER_H
#define RSIA_MODEL_IMAGE_TRANSPORT_PUBLISHER_H

#include <cstdint>
#include <string>

#include <image_transport/single_subscriber_publisher.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

namespace image_transport
{

class Publisher
{
public:
  Publisher();

  uint32_t getNumSubscribers() const;
  std::string getTopic() const;
  void publish(const sensor_msgs::Image& message) const;
  void publish(const sensor_msgs::ImageConstPtr& message) const;
  void shutdown();
  operator void*() const;
  bool operator<(const Publisher& rhs) const;
  bool operator!=(const Publisher& rhs) const;
  bool operator==(const Publisher& rhs) const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_PUBLISHER_H
