// colcon-rsia model of <tf/transform_datatypes.h>: Stamped<T>, StampedTransform
// and the message conversions.
#ifndef RSIA_MODEL_TF_TRANSFORM_DATATYPES_H
#define RSIA_MODEL_TF_TRANSFORM_DATATYPES_H

#include <string>

#include <geometry_msgs/Point.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Vector3.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <ros/console.h>
#include <ros/time.h>
#include <tf/LinearMath/Transform.h>

namespace tf
{

typedef tf::Vector3 Point;
typedef tf::Transform Pose;

static const double QUATERNION_TOLERANCE = 0.1f;

template <typename T>
class Stamped : public T
{
public:
  ros::Time stamp_;
  std::string frame_id_;

  Stamped();
  Stamped(const T& input, const ros::Time& timestamp, const std::string& frame_id);
  void setData(const T& input);
};

template <typename T>
bool operator==(const Stamped<T>& a, const Stamped<T>& b);

class StampedTransform : public tf::Transform
{
public:
  ros::Time stamp_;
  std::string frame_id_;
  std::string child_frame_id_;

  StampedTransform(const tf::Transform& input, const ros::Time& timestamp, const std::string& frame_id,
                   const std::string& child_frame_id);
  StampedTransform();
  void setData(const tf::Transform& input);
};

bool operator==(const StampedTransform& a, const StampedTransform& b);

void quaternionMsgToTF(const geometry_msgs::Quaternion& msg, Quaternion& bt);
void quaternionTFToMsg(const Quaternion& bt, geometry_msgs::Quaternion& msg);
double getYaw(const Quaternion& bt_q);
double getYaw(const geometry_msgs::Quaternion& msg_q);
tf::Quaternion createQuaternionFromRPY(double roll, double pitch, double yaw);
Quaternion createQuaternionFromYaw(double yaw);
geometry_msgs::Quaternion createQuaternionMsgFromYaw(double yaw);
geometry_msgs::Quaternion createQuaternionMsgFromRollPitchYaw(double roll, double pitch, double yaw);
tf::Quaternion createIdentityQuaternion();
void quaternionStampedMsgToTF(const geometry_msgs::QuaternionStamped& msg, Stamped<Quaternion>& bt);
void quaternionStampedTFToMsg(const Stamped<Quaternion>& bt, geometry_msgs::QuaternionStamped& msg);
void vector3MsgToTF(const geometry_msgs::Vector3& msg_v, Vector3& bt_v);
void vector3TFToMsg(const Vector3& bt_v, geometry_msgs::Vector3& msg_v);
void vector3StampedMsgToTF(const geometry_msgs::Vector3Stamped& msg, Stamped<Vector3>& bt);
void vector3StampedTFToMsg(const Stamped<Vector3>& bt, geometry_msgs::Vector3Stamped& msg);
void pointMsgToTF(const geometry_msgs::Point& msg_v, Point& bt_v);
void pointTFToMsg(const Point& bt_v, geometry_msgs::Point& msg_v);
void pointStampedMsgToTF(const geometry_msgs::PointStamped& msg, Stamped<Point>& bt);
void pointStampedTFToMsg(const Stamped<Point>& bt, geometry_msgs::PointStamped& msg);
void transformMsgToTF(const geometry_msgs::Transform& msg, Transform& bt);
void transformTFToMsg(const Transform& bt, geometry_msgs::Transform& msg);
void transformStampedMsgToTF(const geometry_msgs::TransformStamped& msg, StampedTransform& bt);
void transformStampedTFToMsg(const StampedTransform& bt, geometry_msgs::TransformStamped& msg);
void poseMsgToTF(const geometry_msgs::Pose& msg, Pose& bt);
void poseTFToMsg(const Pose& bt, geometry_msgs::Pose& msg);
void poseStampedMsgToTF(const geometry_msgs::PoseStamped& msg, Stamped<Pose>& bt);
void poseStampedTFToMsg(const Stamped<Pose>& bt, geometry_msgs::PoseStamped& msg);

}  // namespace tf

#endif  // RSIA_MODEL_TF_TRANSFORM_DATATYPES_H
