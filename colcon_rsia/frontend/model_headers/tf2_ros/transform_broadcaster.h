// colcon-rsia model of <tf2_ros/transform_broadcaster.h>: every object is a
// publisher of /tf; sendTransform is its publish site.
#ifndef RSIA_MODEL_TF2_ROS_TRANSFORM_BROADCASTER_H
#define RSIA_MODEL_TF2_ROS_TRANSFORM_BROADCASTER_H

#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>

namespace tf2_ros
{

class TransformBroadcaster
{
public:
  TransformBroadcaster();

  void sendTransform(const geometry_msgs::TransformStamped& transform);
  void sendTransform(const std::vector<geometry_msgs::TransformStamped>& transforms);
};

}  // namespace tf2_ros

#endif  // RSIA_MODEL_TF2_ROS_TRANSFORM_BROADCASTER_H
