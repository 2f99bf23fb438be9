// colcon-rsia model of <ros/common.h>.
//
// The real roscpp headers bring in much of the C++ standard library, and user
// code compiled against them often relies on that (std::shared_ptr without
// <memory>, std::cout without <iostream>): see rsia_model/std.h.
#ifndef RSIA_MODEL_ROS_COMMON_H
#define RSIA_MODEL_ROS_COMMON_H

#include <rsia_model/std.h>

#include <boost/bind/bind.hpp>
#include <boost/function.hpp>
#include <boost/make_shared.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/assert.h>
#include <ros/exception.h>
#include <ros/forwards.h>
#include <ros/macros.h>
#include <ros/types.h>

#define ROS_VERSION_MAJOR 1
#define ROS_VERSION_MINOR 16
#define ROS_VERSION_PATCH 0
#define ROS_VERSION_COMBINED(major, minor, patch) (((major) << 20) | ((minor) << 10) | (patch))
#define ROS_VERSION ROS_VERSION_COMBINED(ROS_VERSION_MAJOR, ROS_VERSION_MINOR, ROS_VERSION_PATCH)
#define ROS_VERSION_GE(a1, a2, a3, b1, b2, b3) \
  (ROS_VERSION_COMBINED(a1, a2, a3) >= ROS_VERSION_COMBINED(b1, b2, b3))
#define ROS_VERSION_MINIMUM(major, minor, patch) \
  ROS_VERSION_GE(ROS_VERSION_MAJOR, ROS_VERSION_MINOR, ROS_VERSION_PATCH, major, minor, patch)

namespace ros
{

void disableAllSignalsInThisThread();

}  // namespace ros

#endif  // RSIA_MODEL_ROS_COMMON_H
