// colcon-rsia model of <tf2_ros/buffer.h>: tf2_ros::Buffer (the timeout forms
// of lookupTransform/canTransform, and those of tf2::BufferCore by `using`).
#ifndef RSIA_MODEL_TF2_ROS_BUFFER_H
#define RSIA_MODEL_TF2_ROS_BUFFER_H

// ROS 1 and ROS 2 share this include name: a ROS 2 TU includes
// <rclcpp/rclcpp.hpp> first (directly or through its own headers),
// which defines RSIA_MODEL_RCLCPP; then the ROS 2 class is declared.
#ifdef RSIA_MODEL_RCLCPP
#include <string>
#include <rsia_model/message.h>

namespace tf2_ros
{

class Buffer
{
public:
  template<class NodeT = rclcpp::Node::SharedPtr>
  explicit Buffer(rclcpp::Clock::SharedPtr clock);
  template<class TimeT>
  rsia_model::Fields lookupTransform(
    const std::string & target_frame, const std::string & source_frame,
    const TimeT & time) const;
  template<class TimeT, class DurationT>
  rsia_model::Fields lookupTransform(
    const std::string & target_frame, const std::string & source_frame,
    const TimeT & time, const DurationT timeout) const;
  template<class TimeT>
  bool canTransform(
    const std::string & target_frame, const std::string & source_frame,
    const TimeT & time, std::string * errstr = nullptr) const;
};

}  // namespace tf2_ros
#else  // ROS 1

#include <string>

#include <ros/ros.h>
#include <tf2/buffer_core.h>
#include <tf2_ros/buffer_interface.h>

namespace tf2_ros
{

class Buffer : public BufferInterface, public tf2::BufferCore
{
public:
  using tf2::BufferCore::lookupTransform;
  using tf2::BufferCore::canTransform;

  Buffer(ros::Duration cache_time = ros::Duration(BufferCore::DEFAULT_CACHE_TIME), bool debug = false);

  virtual geometry_msgs::TransformStamped lookupTransform(const std::string& target_frame,
                                                          const std::string& source_frame,
                                                          const ros::Time& time,
                                                          const ros::Duration timeout) const;
  virtual geometry_msgs::TransformStamped lookupTransform(const std::string& target_frame,
                                                          const ros::Time& target_time,
                                                          const std::string& source_frame,
                                                          const ros::Time& source_time,
                                                          const std::string& fixed_frame,
                                                          const ros::Duration timeout) const;
  virtual bool canTransform(const std::string& target_frame, const std::string& source_frame,
                            const ros::Time& target_time, const ros::Duration timeout,
                            std::string* errstr = NULL) const;
  virtual bool canTransform(const std::string& target_frame, const ros::Time& target_time,
                            const std::string& source_frame, const ros::Time& source_time,
                            const std::string& fixed_frame, const ros::Duration timeout,
                            std::string* errstr = NULL) const;
};

static const std::string threading_error = "Do not call canTransform or lookupTransform with a timeout "
                                           "unless another thread populates the buffer.";

}  // namespace tf2_ros

#endif  // RSIA_MODEL_RCLCPP

#endif  // RSIA_MODEL_TF2_ROS_BUFFER_H
