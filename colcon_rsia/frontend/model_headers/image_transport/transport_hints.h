// colcon-rsia model of <image_transport/transport_hints.h>.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_TRANSPORT_HINTS_H
#define RSIA_MODEL_IMAGE_TRANSPORT_TRANSPORT_HINTS_H

#include <string>

#include <ros/ros.h>

namespace image_transport
{

class TransportHints
{
public:
  TransportHints(const std::string& default_transport = "raw",
                 const ros::TransportHints& ros_hints = ros::TransportHints(),
                 const ros::NodeHandle& parameter_nh = ros::NodeHandle("~"),
                 const std::string& parameter_name = "image_transport");

  const std::string& getTransport() const;
  const ros::TransportHints& getRosHints() const;
  const ros::NodeHandle& getParameterNH() const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_TRANSPORT_HINTS_H
