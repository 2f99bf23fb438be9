// colcon-rsia model of <tf2_ros/static_transform_broadcaster.h>: every object is
// a (latched) publisher of /tf_static; sendTransform is its publish site.
#ifndef RSIA_MODEL_TF2_ROS_STATIC_TRANSFORM_BROADCASTER_H
#define RSIA_MODEL_TF2_ROS_STATIC_TRANSFORM_BROADCASTER_H

// ROS 1 and ROS 2 share this include name: a ROS 2 TU includes
// <rclcpp/rclcpp.hpp> first (directly or through its own headers),
// which defines RSIA_MODEL_RCLCPP; then the ROS 2 class is declared.
#ifdef RSIA_MODEL_RCLCPP
#include <string>

namespace tf2_ros
{

class StaticTransformBroadcaster
{
public:
  template<class NodeT>
  StaticTransformBroadcaster(NodeT && node);
  template<class NodeT>
  StaticTransformBroadcaster(NodeT && node, const rclcpp::QoS & qos);
  template<class TransformT>
  void sendTransform(const TransformT & transform);
};

}  // namespace tf2_ros
#else  // ROS 1

#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>

namespace tf2_ros
{

class StaticTransformBroadcaster
{
public:
  StaticTransformBroadcaster();

  void sendTransform(const geometry_msgs::TransformStamped& transform);
  void sendTransform(const std::vector<geometry_msgs::TransformStamped>& transforms);
};

}  // namespace tf2_ros

#endif  // RSIA_MODEL_RCLCPP

#endif  // RSIA_MODEL_TF2_ROS_STATIC_TRANSFORM_BROADCASTER_H
