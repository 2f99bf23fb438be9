// colcon-rsia model of <ros/message_operations.h>: the printer a
// generated message specialises (`template<> struct Printer<MyType>`).
#ifndef RSIA_MODEL_ROS_MESSAGE_OPERATIONS_H
#define RSIA_MODEL_ROS_MESSAGE_OPERATIONS_H

#include <ostream>
#include <string>

namespace ros
{
namespace message_operations
{

template <typename M>
struct Printer
{
  template <typename Stream>
  static void stream(Stream &, const std::string &, const M &) {}
};

}  // namespace message_operations
}  // namespace ros

#endif  // RSIA_MODEL_ROS_MESSAGE_OPERATIONS_H
