// tf_monitor: looks up map -> base_link with both tf APIs and reports it.
//
// RSIA patterns covered here:
// - tf listeners count as subscribers (of /tf and /tf_static): pattern 1 does not apply
//   although the node calls no subscribe().
// - RATE LOOP in main (literal 5 Hz) -> independent, rate_loop, rate_hz 5.0.
// - MIXED: the helper publishDelay() is called from the Rate loop (5 Hz) AND from a lambda
//   timer callback (1 Hz) -> independent, mixed; two different rates -> rate_hz null.
// APIs covered: tf::TransformListener::lookupTransform, tf2_ros::Buffer +
// tf2_ros::TransformListener, tf2_ros::Buffer::lookupTransform, createTimer with a lambda.
#include <string>

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <tf/transform_listener.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

namespace
{
ros::Publisher g_delay_pub;
}  // namespace

// Helper: publishes how old the newest target <- source transform is.
// Called from the Rate loop in main and from the timer lambda.
void publishDelay(const tf2_ros::Buffer& buffer, const std::string& target, const std::string& source)
{
  std_msgs::Float64 delay;
  try
  {
    const geometry_msgs::TransformStamped t = buffer.lookupTransform(target, source, ros::Time(0));
    delay.data = (ros::Time::now() - t.header.stamp).toSec();
  }
  catch (const tf2::TransformException&)
  {
    delay.data = -1.0;
  }
  // EXPECT tf_delay: independent, mixed (rate loop in main at 5 Hz + timer lambda at 1 Hz),
  // rate_hz null (two different rates).
  g_delay_pub.publish(delay);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "tf_monitor");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  const std::string target = pnh.param<std::string>("target_frame", "map");
  const std::string source = pnh.param<std::string>("source_frame", "base_link");

  // API: tf::TransformListener (subscribes /tf and /tf_static).
  tf::TransformListener legacy_listener;
  // API: tf2_ros::Buffer + tf2_ros::TransformListener (subscribes /tf and /tf_static).
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);

  ros::Publisher pose_pub = nh.advertise<geometry_msgs::PoseStamped>("base_pose", 10);
  ros::Publisher legacy_pub = nh.advertise<geometry_msgs::PointStamped>("base_position_legacy", 10);
  g_delay_pub = nh.advertise<std_msgs::Float64>("tf_delay", 10);

  // API: ros::NodeHandle::createTimer with a lambda callback (1.0 s -> 1 Hz).
  ros::Timer delay_timer = nh.createTimer(
      ros::Duration(1.0),
      [&](const ros::TimerEvent&) { publishDelay(buffer, target, source); });

  // API: ros::Rate loop at a literal rate.
  ros::Rate rate(5.0);
  while (nh.ok())
  {
    ros::spinOnce();
    try
    {
      // API: tf2_ros::Buffer::lookupTransform.
      const geometry_msgs::TransformStamped t =
          buffer.lookupTransform(target, source, ros::Time(0), ros::Duration(0.1));
      geometry_msgs::PoseStamped pose;
      pose.header = t.header;
      pose.pose.position.x = t.transform.translation.x;
      pose.pose.position.y = t.transform.translation.y;
      pose.pose.position.z = t.transform.translation.z;
      pose.pose.orientation = t.transform.rotation;
      // EXPECT base_pose: independent, rate_loop (5 Hz Rate loop in main), rate_hz 5.0.
      pose_pub.publish(pose);

      // API: tf::TransformListener::lookupTransform (inherited from tf::Transformer).
      tf::StampedTransform legacy;
      legacy_listener.lookupTransform(target, source, ros::Time(0), legacy);
      geometry_msgs::PointStamped point;
      point.header.stamp = legacy.stamp_;
      point.header.frame_id = target;
      point.point.x = legacy.getOrigin().x();
      point.point.y = legacy.getOrigin().y();
      point.point.z = legacy.getOrigin().z();
      // EXPECT base_position_legacy: independent, rate_loop (same loop), rate_hz 5.0.
      legacy_pub.publish(point);
    }
    catch (const tf2::TransformException& ex)  // tf::TransformException is the same type
    {
      ROS_WARN_THROTTLE(5.0, "tf_monitor: %s", ex.what());
    }
    publishDelay(buffer, target, source);
    rate.sleep();
  }
  return 0;
}
