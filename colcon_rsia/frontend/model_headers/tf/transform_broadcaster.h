// colcon-rsia model of <tf/transform_broadcaster.h>: every object is a
// publisher of /tf; sendTransform is its publish site.
#ifndef RSIA_MODEL_TF_TRANSFORM_BROADCASTER_H
#define RSIA_MODEL_TF_TRANSFORM_BROADCASTER_H

#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <tf/tf.h>
#include <tf2_ros/transform_broadcaster.h>

namespace tf
{

class TransformBroadcaster
{
public:
  TransformBroadcaster();

  void sendTransform(const StampedTransform& transform);
  void sendTransform(const std::vector<StampedTransform>& transforms);
  void sendTransform(const geometry_msgs::TransformStamped& transform);
  void sendTransform(const std::vector<geometry_msgs::TransformStamped>& transforms);
};

}  // namespace tf

#endif  // RSIA_MODEL_TF_TRANSFORM_BROADCASTER_H
