// colcon-rsia model of <image_transport/camera_publisher.hpp> (ROS 2): an
// image topic and `<dirname>/camera_info` published together (the UniquePtr
// forms are Jazzy+).
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_PUBLISHER_HPP
#define RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_PUBLISHER_HPP

#include <cstddef>
#include <string>

#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/camera_info.hpp>
#include <sensor_msgs/msg/image.hpp>

namespace image_transport
{

class CameraPublisher
{
public:
  CameraPublisher();

  size_t getNumSubscribers() const;
  std::string getTopic() const;
  std::string getInfoTopic() const;
  void publish(
    const sensor_msgs::msg::Image & image,
    const sensor_msgs::msg::CameraInfo & info) const;
  void publish(
    const sensor_msgs::msg::Image::ConstSharedPtr & image,
    const sensor_msgs::msg::CameraInfo::ConstSharedPtr & info) const;
  void publish(
    sensor_msgs::msg::Image::UniquePtr image,
    sensor_msgs::msg::CameraInfo::UniquePtr info) const;
  void publish(
    sensor_msgs::msg::Image & image, sensor_msgs::msg::CameraInfo & info,
    rclcpp::Time stamp) const;
  void publish(
    sensor_msgs::msg::Image::UniquePtr image,
    sensor_msgs::msg::CameraInfo::UniquePtr info, rclcpp::Time stamp) const;
  // values of a library the model lacks (see publisher.hpp)
  template<class AnyT, class InfoT, typename std::enable_if<
      std::is_base_of<rsia_model::Any, typename std::decay<AnyT>::type>::value, int>::type = 0>
  void publish(AnyT && image, InfoT && info) const;
  void shutdown();
  operator void *() const;
  bool operator<(const CameraPublisher & rhs) const;
  bool operator!=(const CameraPublisher & rhs) const;
  bool operator==(const CameraPublisher & rhs) const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_PUBLISHER_HPP
