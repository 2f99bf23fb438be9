// colcon-rsia model of <ros/names.h>.
#ifndef RSIA_MODEL_ROS_NAMES_H
#define RSIA_MODEL_ROS_NAMES_H

#include <string>

#include <ros/forwards.h>

namespace ros
{

namespace names
{

const M_string& getRemappings();
const M_string& getUnresolvedRemappings();
std::string clean(const std::string& name);
std::string resolve(const std::string& name, bool remap = true);
std::string resolve(const std::string& ns, const std::string& name, bool remap = true);
std::string append(const std::string& left, const std::string& right);
std::string remap(const std::string& name);
bool validate(const std::string& name, std::string& error);
std::string parentNamespace(const std::string& name);

}  // namespace names

}  // namespace ros

#endif  // RSIA_MODEL_ROS_NAMES_H
