// colcon-rsia model of <image_transport/transport_hints.hpp> (ROS 2): the
// transport comes from the node parameter `image_transport` (default "raw").
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_TRANSPORT_HINTS_HPP
#define RSIA_MODEL_IMAGE_TRANSPORT_TRANSPORT_HINTS_HPP

#include <string>

#include <rclcpp/rclcpp.hpp>

namespace image_transport
{

class TransportHints
{
public:
  TransportHints(
    const rclcpp::Node * node,
    const std::string & default_transport = "raw",
    const std::string & parameter_name = "image_transport");
  const std::string & getTransport() const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_TRANSPORT_HINTS_HPP
