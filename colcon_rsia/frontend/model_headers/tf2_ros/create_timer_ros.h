// colcon-rsia model of <tf2_ros/create_timer_ros.h> (ROS 2): the timer
// interface a Buffer uses for waitForTransform (no timer of the user's).
#ifndef RSIA_MODEL_TF2_ROS_CREATE_TIMER_ROS_H
#define RSIA_MODEL_TF2_ROS_CREATE_TIMER_ROS_H

#include <rclcpp/rclcpp.hpp>
#include <tf2_ros/create_timer_interface.h>

namespace tf2_ros
{

class CreateTimerROS : public CreateTimerInterface
{
public:
  CreateTimerROS(
    rclcpp::node_interfaces::NodeBaseInterface::SharedPtr node_base,
    rclcpp::node_interfaces::NodeTimersInterface::SharedPtr node_timers,
    rclcpp::CallbackGroup::SharedPtr callback_group = nullptr);
};

}  // namespace tf2_ros

#endif  // RSIA_MODEL_TF2_ROS_CREATE_TIMER_ROS_H
