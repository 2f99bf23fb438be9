// colcon-rsia model of <tf2_ros/transform_listener.h>: every object subscribes
// to /tf and /tf_static.
#ifndef RSIA_MODEL_TF2_ROS_TRANSFORM_LISTENER_H
#define RSIA_MODEL_TF2_ROS_TRANSFORM_LISTENER_H

// ROS 1 and ROS 2 share this include name: a ROS 2 TU includes
// <rclcpp/rclcpp.hpp> first (directly or through its own headers),
// which defines RSIA_MODEL_RCLCPP; then the ROS 2 class is declared.
#ifdef RSIA_MODEL_RCLCPP
#include <string>

namespace tf2_ros
{

class Buffer;
class TransformListener
{
public:
  explicit TransformListener(Buffer & buffer, bool spin_thread = true);
  template<class NodeT>
  TransformListener(Buffer & buffer, NodeT && node, bool spin_thread = true);
};

}  // namespace tf2_ros
#else  // ROS 1

#include <boost/thread.hpp>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>

namespace tf2_ros
{

class TransformListener
{
public:
  TransformListener(tf2::BufferCore& buffer, bool spin_thread = true,
                    ros::TransportHints transport_hints = ros::TransportHints());
  TransformListener(tf2::BufferCore& buffer, const ros::NodeHandle& nh, bool spin_thread = true,
                    ros::TransportHints transport_hints = ros::TransportHints());
  ~TransformListener();
};

}  // namespace tf2_ros

#endif  // RSIA_MODEL_RCLCPP

#endif  // RSIA_MODEL_TF2_ROS_TRANSFORM_LISTENER_H
