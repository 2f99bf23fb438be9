// colcon-rsia model of <tf2_ros/create_timer_interface.h> (ROS 2).
#ifndef RSIA_MODEL_TF2_ROS_CREATE_TIMER_INTERFACE_H
#define RSIA_MODEL_TF2_ROS_CREATE_TIMER_INTERFACE_H

#include <memory>

namespace tf2_ros
{

class CreateTimerInterface
{
public:
  using SharedPtr = std::shared_ptr<CreateTimerInterface>;
  virtual ~CreateTimerInterface();
};

}  // namespace tf2_ros

#endif  // RSIA_MODEL_TF2_ROS_CREATE_TIMER_INTERFACE_H
