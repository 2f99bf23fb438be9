// colcon-rsia model of <tf2_ros/static_transform_broadcaster.h>: every object is
// a (latched) publisher of /tf_static; sendTransform is its publish site.
#ifndef RSIA_MODEL_TF2_ROS_STATIC_TRANSFORM_BROADCASTER_H
#define RSIA_MODEL_TF2_ROS_STATIC_TRANSFORM_BROADCASTER_H

// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
#ifdef RSIA_MODEL_RCLCPP
#include <memory>
#include <string>
#include <vector>

#include <geometry_msgs/msg/transform_stamped.hpp>
#include <tf2_ros/qos.hpp>

namespace tf2_ros
{

class StaticTransformBroadcaster
{
public:
  template<class NodeT, class AllocatorT = std::allocator<void>>
  StaticTransformBroadcaster(
    NodeT && node, const rclcpp::QoS & qos = StaticBroadcasterQoS(),
    const rclcpp::PublisherOptionsWithAllocator<AllocatorT> & options =
    rclcpp::PublisherOptionsWithAllocator<AllocatorT>());
  void sendTransform(const geometry_msgs::msg::TransformStamped & transform);
  void sendTransform(const std::vector<geometry_msgs::msg::TransformStamped> & transforms);
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
