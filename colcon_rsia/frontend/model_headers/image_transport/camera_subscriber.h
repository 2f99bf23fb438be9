// colcon-rsia model of <image_transport/camera_subscriber.h>.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_SUBSCRIBER_H
#define RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_SUBSCRIBER_H

#include <cstdint>
#include <string>

#include <boost/function.hpp>
#include <image_transport/transport_hints.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

namespace image_transport
{

class ImageTransport;

class CameraSubscriber
{
public:
  typedef boost::function<void(const sensor_msgs::ImageConstPtr&, const sensor_msgs::CameraInfoConstPtr&)>
      Callback;

  CameraSubscriber();

  std::string getTopic() const;
  std::string getInfoTopic() const;
  uint32_t getNumPublishers() const;
  std::string getTransport() const;
  void shutdown();
  operator void*() const;
  bool operator<(const CameraSubscriber& rhs) const;
  bool operator!=(const CameraSubscriber& rhs) const;
  bool operator==(const CameraSubscriber& rhs) const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_SUBSCRIBER_H
