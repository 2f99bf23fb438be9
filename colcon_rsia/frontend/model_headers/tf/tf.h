// colcon-rsia model of <tf/tf.h>: tf::Transformer (the base of
// tf::TransformListener, where lookupTransform & co. are declared).
#ifndef RSIA_MODEL_TF_TF_H
#define RSIA_MODEL_TF_TF_H

#include <rsia_model/std.h>

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistStamped.h>
#include <ros/macros.h>
#include <tf/exceptions.h>
#include <tf/transform_datatypes.h>
#include <tf2_ros/buffer.h>

namespace tf
{

std::string resolve(const std::string& prefix, const std::string& frame_name);
std::string strip_leading_slash(const std::string& frame_name);

class Transformer
{
public:
  static const unsigned int MAX_GRAPH_DEPTH = 100UL;
  static const double DEFAULT_CACHE_TIME;
  static const int64_t DEFAULT_MAX_EXTRAPOLATION_DISTANCE = 0ULL;

  Transformer(bool interpolating = true, ros::Duration cache_time_ = ros::Duration(DEFAULT_CACHE_TIME));
  virtual ~Transformer(void);

  void clear();
  bool setTransform(const StampedTransform& transform, const std::string& authority = "default_authority");
  void lookupTransform(const std::string& target_frame, const std::string& source_frame,
                       const ros::Time& time, StampedTransform& transform) const;
  void lookupTransform(const std::string& target_frame, const ros::Time& target_time,
                       const std::string& source_frame, const ros::Time& source_time,
                       const std::string& fixed_frame, StampedTransform& transform) const;
  void lookupTwist(const std::string& tracking_frame, const std::string& observation_frame,
                   const std::string& reference_frame, const tf::Point& reference_point,
                   const std::string& reference_point_frame, const ros::Time& time,
                   const ros::Duration& averaging_interval, geometry_msgs::Twist& twist) const;
  void lookupTwist(const std::string& tracking_frame, const std::string& observation_frame,
                   const ros::Time& time, const ros::Duration& averaging_interval,
                   geometry_msgs::Twist& twist) const;
  bool waitForTransform(const std::string& target_frame, const std::string& source_frame,
                        const ros::Time& time, const ros::Duration& timeout,
                        const ros::Duration& polling_sleep_duration = ros::Duration(0.01),
                        std::string* error_msg = NULL) const;
  bool canTransform(const std::string& target_frame, const std::string& source_frame, const ros::Time& time,
                    std::string* error_msg = NULL) const;
  bool canTransform(const std::string& target_frame, const ros::Time& target_time,
                    const std::string& source_frame, const ros::Time& source_time,
                    const std::string& fixed_frame, std::string* error_msg = NULL) const;
  bool waitForTransform(const std::string& target_frame, const ros::Time& target_time,
                        const std::string& source_frame, const ros::Time& source_time,
                        const std::string& fixed_frame, const ros::Duration& timeout,
                        const ros::Duration& polling_sleep_duration = ros::Duration(0.01),
                        std::string* error_msg = NULL) const;
  int getLatestCommonTime(const std::string& source_frame, const std::string& target_frame, ros::Time& time,
                          std::string* error_string) const;
  void transformQuaternion(const std::string& target_frame, const Stamped<tf::Quaternion>& stamped_in,
                           Stamped<tf::Quaternion>& stamped_out) const;
  void transformVector(const std::string& target_frame, const Stamped<tf::Vector3>& stamped_in,
                       Stamped<tf::Vector3>& stamped_out) const;
  void transformPoint(const std::string& target_frame, const Stamped<tf::Point>& stamped_in,
                      Stamped<tf::Point>& stamped_out) const;
  void transformPose(const std::string& target_frame, const Stamped<tf::Pose>& stamped_in,
                     Stamped<tf::Pose>& stamped_out) const;
  void transformQuaternion(const std::string& target_frame, const ros::Time& target_time,
                           const Stamped<tf::Quaternion>& stamped_in, const std::string& fixed_frame,
                           Stamped<tf::Quaternion>& stamped_out) const;
  void transformVector(const std::string& target_frame, const ros::Time& target_time,
                       const Stamped<tf::Vector3>& stamped_in, const std::string& fixed_frame,
                       Stamped<tf::Vector3>& stamped_out) const;
  void transformPoint(const std::string& target_frame, const ros::Time& target_time,
                      const Stamped<tf::Point>& stamped_in, const std::string& fixed_frame,
                      Stamped<tf::Point>& stamped_out) const;
  void transformPose(const std::string& target_frame, const ros::Time& target_time,
                     const Stamped<tf::Pose>& stamped_in, const std::string& fixed_frame,
                     Stamped<tf::Pose>& stamped_out) const;
  void chainAsVector(const std::string& target_frame, ros::Time target_time, const std::string& source_frame,
                     ros::Time source_time, const std::string& fixed_frame,
                     std::vector<std::string>& output) const;
  std::string allFramesAsString() const;
  std::string allFramesAsDot(double current_time = 0) const;
  void getFrameStrings(std::vector<std::string>& ids) const;
  bool getParent(const std::string& frame_id, ros::Time time, std::string& parent) const;
  bool frameExists(const std::string& frame_id_str) const;
  void setExtrapolationLimit(const ros::Duration& distance);
  ros::Duration getCacheLength();
  std::string getTFPrefix() const;
  void setUsingDedicatedThread(bool value);
  bool isUsingDedicatedThread();
  virtual bool ok() const;
};

void assertQuaternionValid(const tf::Quaternion& q);
void assertQuaternionValid(const geometry_msgs::Quaternion& q);

}  // namespace tf

#endif  // RSIA_MODEL_TF_TF_H
