// colcon-rsia model of <image_transport/camera_common.hpp> (ROS 2).
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_COMMON_HPP
#define RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_COMMON_HPP

#include <string>
#include <vector>

namespace image_transport
{

std::string getCameraInfoTopic(const std::string & base_topic);
std::string erase_last_copy(const std::string & input, const std::string & search);
std::vector<std::string> split(
  std::string input, const std::string & delim, int max_splits = 0);

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_COMMON_HPP
