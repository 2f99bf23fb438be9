// colcon-rsia model of <image_transport/camera_subscriber.hpp> (ROS 2): an
// image topic and `<dirname>/camera_info`, delivered together.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_SUBSCRIBER_HPP
#define RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_SUBSCRIBER_HPP

#include <cstddef>
#include <functional>
#include <string>

#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/camera_info.hpp>
#include <sensor_msgs/msg/image.hpp>

namespace image_transport
{

class CameraSubscriber
{
public:
  using Callback = std::function<void (
        const sensor_msgs::msg::Image::ConstSharedPtr &,
        const sensor_msgs::msg::CameraInfo::ConstSharedPtr &)>;

  CameraSubscriber();

  std::string getTopic() const;
  std::string getInfoTopic() const;
  size_t getNumPublishers() const;
  std::string getTransport() const;
  void shutdown();
  operator void *() const;
  bool operator<(const CameraSubscriber & rhs) const;
  bool operator!=(const CameraSubscriber & rhs) const;
  bool operator==(const CameraSubscriber & rhs) const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_SUBSCRIBER_HPP
