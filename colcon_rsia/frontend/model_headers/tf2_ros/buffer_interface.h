// colcon-rsia model of <tf2_ros/buffer_interface.h>.
#ifndef RSIA_MODEL_TF2_ROS_BUFFER_INTERFACE_H
#define RSIA_MODEL_TF2_ROS_BUFFER_INTERFACE_H

#include <string>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2/convert.h>
#include <tf2/exceptions.h>
#include <tf2/transform_datatypes.h>

namespace tf2_ros
{

class BufferInterface
{
public:
  virtual geometry_msgs::TransformStamped lookupTransform(const std::string& target_frame,
                                                          const std::string& source_frame,
                                                          const ros::Time& time,
                                                          const ros::Duration timeout) const = 0;
  virtual geometry_msgs::TransformStamped lookupTransform(const std::string& target_frame,
                                                          const ros::Time& target_time,
                                                          const std::string& source_frame,
                                                          const ros::Time& source_time,
                                                          const std::string& fixed_frame,
                                                          const ros::Duration timeout) const = 0;
  virtual bool canTransform(const std::string& target_frame, const std::string& source_frame,
                            const ros::Time& time, const ros::Duration timeout,
                            std::string* errstr = NULL) const = 0;
  virtual bool canTransform(const std::string& target_frame, const ros::Time& target_time,
                            const std::string& source_frame, const ros::Time& source_time,
                            const std::string& fixed_frame, const ros::Duration timeout,
                            std::string* errstr = NULL) const = 0;

  template <class T>
  T& transform(const T& in, T& out, const std::string& target_frame,
               ros::Duration timeout = ros::Duration(0.0)) const;
  template <class T>
  T transform(const T& in, const std::string& target_frame, ros::Duration timeout = ros::Duration(0.0)) const;
  template <class A, class B>
  B& transform(const A& in, B& out, const std::string& target_frame,
               ros::Duration timeout = ros::Duration(0.0)) const;
  template <class T>
  T& transform(const T& in, T& out, const std::string& target_frame, const ros::Time& target_time,
               const std::string& fixed_frame, ros::Duration timeout = ros::Duration(0.0)) const;
  template <class T>
  T transform(const T& in, const std::string& target_frame, const ros::Time& target_time,
              const std::string& fixed_frame, ros::Duration timeout = ros::Duration(0.0)) const;
  template <class A, class B>
  B& transform(const A& in, B& out, const std::string& target_frame, const ros::Time& target_time,
               const std::string& fixed_frame, ros::Duration timeout = ros::Duration(0.0)) const;

  virtual ~BufferInterface();
};

}  // namespace tf2_ros

#endif  // RSIA_MODEL_TF2_ROS_BUFFER_INTERFACE_H
