// colcon-rsia model of <ros/exception.h>.
#ifndef RSIA_MODEL_ROS_EXCEPTION_H
#define RSIA_MODEL_ROS_EXCEPTION_H

#include <stdexcept>
#include <string>

namespace ros
{

class Exception : public std::runtime_error
{
public:
  Exception(const std::string& what);
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_EXCEPTION_H
