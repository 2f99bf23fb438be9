// colcon-rsia model of <image_transport/publisher.hpp> (ROS 2):
// image_transport::Publisher and its publish site (the UniquePtr form is
// Jazzy+).
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_PUBLISHER_HPP
#define RSIA_MODEL_IMAGE_TRANSPORT_PUBLISHER_HPP

#include <cstddef>
#include <string>

#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/image.hpp>

namespace image_transport
{

class Publisher
{
public:
  Publisher();

  size_t getNumSubscribers() const;
  std::string getTopic() const;
  void publish(const sensor_msgs::msg::Image & message) const;
  void publish(const sensor_msgs::msg::Image::ConstSharedPtr & message) const;
  void publish(sensor_msgs::msg::Image::UniquePtr message) const;
  // a value of a library the model lacks (cv_bridge's toImageMsg()), which
  // converts to a message and to its SharedPtr alike
  template<class AnyT, typename std::enable_if<
      std::is_base_of<rsia_model::Any, typename std::decay<AnyT>::type>::value, int>::type = 0>
  void publish(AnyT && message) const;
  void shutdown();
  operator void *() const;
  bool operator<(const Publisher & rhs) const;
  bool operator!=(const Publisher & rhs) const;
  bool operator==(const Publisher & rhs) const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_PUBLISHER_HPP
