// odom_tf_broadcaster: turns a pose estimate into tf transforms.
//
// RSIA patterns covered here:
// - tf::TransformBroadcaster::sendTransform inside a subscriber callback -> dependent.
// - tf2_ros::TransformBroadcaster::sendTransform inside a timer callback -> independent, timer.
//   The timer period is a preprocessor constant (#define), so rate_hz is known (50.0).
// - A free-function timer callback publishing the pose age -> independent, timer (1.0 Hz).
// APIs covered: subscribe with boost::bind of a free function, createTimer with boost::bind
// of a free function, createTimer with a plain free function.
#include <boost/bind/bind.hpp>
#include <boost/ref.hpp>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <tf/transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

using namespace boost::placeholders;

// tf broadcast period, seconds: a compile-time constant (1 / 0.02 s = 50 Hz).
#define TF_PUBLISH_PERIOD 0.02

namespace
{
geometry_msgs::PoseStamped g_last_pose;
bool g_have_pose = false;
ros::Publisher g_age_pub;
}  // namespace

// Subscriber callback (free function, bound with boost::bind to the legacy broadcaster).
void onPose(const geometry_msgs::PoseStamped::ConstPtr& msg, tf::TransformBroadcaster& legacy)
{
  g_last_pose = *msg;
  g_have_pose = true;

  tf::Transform transform;
  transform.setOrigin(tf::Vector3(msg->pose.position.x, msg->pose.position.y, msg->pose.position.z));
  tf::Quaternion q;
  tf::quaternionMsgToTF(msg->pose.orientation, q);
  transform.setRotation(q);
  // EXPECT /tf (tf::TransformBroadcaster): dependent, none (subscriber callback: one
  // transform per received pose).
  legacy.sendTransform(tf::StampedTransform(transform, msg->header.stamp, "odom", "base_link_measured"));
}

// Timer callback (free function, bound with boost::bind to the tf2 broadcaster).
void publishOdomTf(const ros::TimerEvent& event, tf2_ros::TransformBroadcaster& broadcaster)
{
  if (!g_have_pose)
  {
    return;
  }
  geometry_msgs::TransformStamped t;
  t.header.stamp = event.current_real;
  t.header.frame_id = "odom";
  t.child_frame_id = "base_link";
  t.transform.translation.x = g_last_pose.pose.position.x;
  t.transform.translation.y = g_last_pose.pose.position.y;
  t.transform.translation.z = g_last_pose.pose.position.z;
  t.transform.rotation = g_last_pose.pose.orientation;
  // EXPECT /tf (tf2_ros::TransformBroadcaster): independent, timer (TF_PUBLISH_PERIOD timer),
  // rate_hz 50.0.
  broadcaster.sendTransform(t);
}

// Timer callback (plain free function).
void reportPoseAge(const ros::TimerEvent& /*event*/)
{
  std_msgs::Float64 age;
  age.data = g_have_pose ? (ros::Time::now() - g_last_pose.header.stamp).toSec() : -1.0;
  // EXPECT pose_age: independent, timer (1 s timer), rate_hz 1.0.
  g_age_pub.publish(age);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "odom_tf_broadcaster");
  ros::NodeHandle nh;

  // API: tf::TransformBroadcaster and tf2_ros::TransformBroadcaster (implicit topic /tf).
  tf::TransformBroadcaster legacy_broadcaster;
  tf2_ros::TransformBroadcaster broadcaster;

  g_age_pub = nh.advertise<std_msgs::Float64>("pose_age", 1);

  // API: ros::NodeHandle::subscribe with boost::bind of a free function.
  ros::Subscriber pose_sub = nh.subscribe<geometry_msgs::PoseStamped>(
      "pose", 10, boost::bind(&onPose, _1, boost::ref(legacy_broadcaster)));

  // API: ros::NodeHandle::createTimer with boost::bind of a free function; #define period.
  ros::Timer tf_timer = nh.createTimer(ros::Duration(TF_PUBLISH_PERIOD),
                                       boost::bind(&publishOdomTf, _1, boost::ref(broadcaster)));
  // API: ros::NodeHandle::createTimer with a plain free function.
  ros::Timer age_timer = nh.createTimer(ros::Duration(1.0), reportPoseAge);

  ros::spin();
  return 0;
}
