// colcon-rsia model of <image_transport/camera_common.h>.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_COMMON_H
#define RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_COMMON_H

#include <string>
#include <vector>

namespace image_transport
{

std::string getCameraInfoTopic(const std::string& base_topic);
std::vector<std::string> getCameraInfoTopics(const std::string& base_topic);

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_CAMERA_COMMON_H
