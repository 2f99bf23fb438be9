// colcon-rsia model of <image_transport/camera_publisher.h>: the publisher of an
// image and its camera_info, and its publish site.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_PUBLISHER_H
#define RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_PUBLISHER_H

#include <cstdint>
#include <string>

#include <image_transport/single_subscriber_publisher.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

namespace image_transport
{

class ImageTransport;

class CameraPublisher
{
public:
  CameraPublisher();

  uint32_t getNumSubscribers() const;
  std::string getTopic() const;
  std::string getInfoTopic() const;
  void publish(const sensor_msgs::Image& image, const sensor_msgs::CameraInfo& info) const;
  void publish(const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info) const;
  void publish(sensor_msgs::Image& image, sensor_msgs::CameraInfo& info, ros::Time stamp) const;
  void shutdown();
  operator void*() const;
  bool operator<(const CameraPublisher& rhs) const;
  bool operator!=(const CameraPublisher& rhs) const;
  bool operator==(const CameraPublisher& rhs) const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_PUBLISHER_H
