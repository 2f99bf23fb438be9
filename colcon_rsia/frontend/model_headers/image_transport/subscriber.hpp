// colcon-rsia model of <image_transport/subscriber.hpp> (ROS 2).
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_SUBSCRIBER_HPP
#define RSIA_MODEL_IMAGE_TRANSPORT_SUBSCRIBER_HPP

#include <cstddef>
#include <functional>
#include <string>

#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/image.hpp>

namespace image_transport
{

class Subscriber
{
public:
  using Callback = std::function<void (const sensor_msgs::msg::Image::ConstSharedPtr &)>;

  Subscriber();

  std::string getTopic() const;
  size_t getNumPublishers() const;
  std::string getTransport() const;
  void shutdown();
  operator void *() const;
  bool operator<(const Subscriber & rhs) const;
  bool operator!=(const Subscriber & rhs) const;
  bool operator==(const Subscriber & rhs) const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_SUBSCRIBER_HPP
