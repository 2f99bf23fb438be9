// laser_driver: simulated planar laser scanner.
//
// RSIA pattern covered here: NO SUBSCRIBERS (paper pattern 1).
// This node creates no subscriber, no service server, no action server and no tf listener,
// so every publisher of the node is rate-independent, whatever its publish path looks like.
// The main loop is a plain `while (ros::ok())` with NO ros::Rate: it is paced only by the
// (simulated) blocking device read. Pattern 1 gives rate_hz null for every publisher.
#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <tf2_ros/static_transform_broadcaster.h>

namespace
{

const int kBeams = 360;

// Blocks until the device has finished one revolution (simulated: ~40 Hz spinning head),
// then fills `ranges` with a synthetic room.
bool readRevolution(std::vector<float>& ranges, int revolution)
{
  std::this_thread::sleep_for(std::chrono::milliseconds(25));
  ranges.resize(kBeams);
  for (int i = 0; i < kBeams; ++i)
  {
    const double angle = 2.0 * M_PI * i / kBeams;
    ranges[i] = static_cast<float>(3.0 + 0.5 * std::sin(4.0 * angle + 0.01 * revolution));
  }
  return true;
}

geometry_msgs::TransformStamped makeMountTransform(const std::string& frame_id)
{
  geometry_msgs::TransformStamped mount;
  mount.header.stamp = ros::Time::now();
  mount.header.frame_id = "base_link";
  mount.child_frame_id = frame_id;
  mount.transform.translation.x = 0.20;
  mount.transform.translation.z = 0.35;
  mount.transform.rotation.w = 1.0;
  return mount;
}

}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "laser_driver");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");

  const std::string frame_id = pnh.param<std::string>("frame_id", "laser");

  // API: ros::NodeHandle::advertise, template form.
  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("scan", 10);
  // API: ros::NodeHandle::advertise with latch = true.
  ros::Publisher info_pub = nh.advertise<std_msgs::String>("laser_info", 1, true);

  // API: tf2_ros::StaticTransformBroadcaster (implicit topic /tf_static).
  tf2_ros::StaticTransformBroadcaster static_broadcaster;

  // EXPECT /tf_static: independent, no_subscribers (node has no subscribers), rate_hz null.
  static_broadcaster.sendTransform(makeMountTransform(frame_id));

  std_msgs::String info;
  info.data = "simulated 360-beam scanner, frame " + frame_id;
  // EXPECT laser_info: independent, no_subscribers. A one-shot publish from main would be
  // dependent in a node that subscribes; pattern 1 overrides that here.
  info_pub.publish(info);

  sensor_msgs::LaserScan scan;
  scan.header.frame_id = frame_id;
  scan.angle_min = 0.0f;
  scan.angle_max = static_cast<float>(2.0 * M_PI);
  scan.angle_increment = static_cast<float>(2.0 * M_PI / kBeams);
  scan.range_min = 0.05f;
  scan.range_max = 12.0f;

  int revolution = 0;
  // Plain loop WITHOUT a ros::Rate: paced by the blocking device read only.
  while (ros::ok())
  {
    if (!readRevolution(scan.ranges, revolution++))
    {
      continue;
    }
    scan.header.stamp = ros::Time::now();
    // EXPECT scan: independent, no_subscribers (no Rate here, but the node subscribes to
    // nothing), rate_hz null.
    scan_pub.publish(scan);
    ros::spinOnce();
  }
  return 0;
}
