// colcon-rsia model of <tf/transform_listener.h>: every object subscribes to
// /tf and /tf_static; lookupTransform & co. come from tf::Transformer.
#ifndef RSIA_MODEL_TF_TRANSFORM_LISTENER_H
#define RSIA_MODEL_TF_TRANSFORM_LISTENER_H

#include <string>

#include <boost/thread.hpp>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <ros/callback_queue.h>
#include <ros/macros.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud.h>
#include <std_msgs/Empty.h>
#include <tf/tf.h>
#include <tf2_ros/transform_listener.h>

namespace tf
{

std::string getPrefixParam(ros::NodeHandle& nh);
std::string remap(const std::string& frame_id);

class TransformListener : public Transformer
{
public:
  TransformListener(ros::Duration max_cache_time = ros::Duration(DEFAULT_CACHE_TIME), bool spin_thread = true);
  TransformListener(const ros::NodeHandle& nh, ros::Duration max_cache_time = ros::Duration(DEFAULT_CACHE_TIME),
                    bool spin_thread = true);
  ~TransformListener();

  using Transformer::transformPoint;
  using Transformer::transformPose;
  using Transformer::transformQuaternion;
  using Transformer::transformVector;

  void transformQuaternion(const std::string& target_frame, const geometry_msgs::QuaternionStamped& stamped_in,
                           geometry_msgs::QuaternionStamped& stamped_out) const;
  void transformVector(const std::string& target_frame, const geometry_msgs::Vector3Stamped& stamped_in,
                       geometry_msgs::Vector3Stamped& stamped_out) const;
  void transformPoint(const std::string& target_frame, const geometry_msgs::PointStamped& stamped_in,
                      geometry_msgs::PointStamped& stamped_out) const;
  void transformPose(const std::string& target_frame, const geometry_msgs::PoseStamped& stamped_in,
                     geometry_msgs::PoseStamped& stamped_out) const;
  void transformQuaternion(const std::string& target_frame, const ros::Time& target_time,
                           const geometry_msgs::QuaternionStamped& qin, const std::string& fixed_frame,
                           geometry_msgs::QuaternionStamped& qout) const;
  void transformVector(const std::string& target_frame, const ros::Time& target_time,
                       const geometry_msgs::Vector3Stamped& vin, const std::string& fixed_frame,
                       geometry_msgs::Vector3Stamped& vout) const;
  void transformPoint(const std::string& target_frame, const ros::Time& target_time,
                      const geometry_msgs::PointStamped& pin, const std::string& fixed_frame,
                      geometry_msgs::PointStamped& pout) const;
  void transformPose(const std::string& target_frame, const ros::Time& target_time,
                     const geometry_msgs::PoseStamped& pin, const std::string& fixed_frame,
                     geometry_msgs::PoseStamped& pout) const;
  void transformPointCloud(const std::string& target_frame, const sensor_msgs::PointCloud& pcin,
                           sensor_msgs::PointCloud& pcout) const;
  void transformPointCloud(const std::string& target_frame, const ros::Time& target_time,
                           const sensor_msgs::PointCloud& pcin, const std::string& fixed_frame,
                           sensor_msgs::PointCloud& pcout) const;
  std::string resolve(const std::string& frame_name);
};

}  // namespace tf

#endif  // RSIA_MODEL_TF_TRANSFORM_LISTENER_H
