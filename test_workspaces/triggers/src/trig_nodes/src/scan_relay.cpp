// scan_relay: re-publishes /scan in the odom frame.
// - /scan: its callback publishes /scan_relayed -> trigger.
// - /joint_states: the callback only caches the message -> not a trigger.
// - tf2_ros::TransformListener (subscribes /tf and /tf_static) + lookupTransform in the
//   /scan callback: a plain listener -> not a trigger.
// EXPECT /scan_relayed: dependent; triggers [/scan]; the paper: every input.
// EXPECT rate /scan_relayed: follows /scan = 10 Hz.
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2/exceptions.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

class ScanRelay
{
public:
  explicit ScanRelay(ros::NodeHandle& nh) : listener_(buffer_)
  {
    relayed_pub_ = nh.advertise<sensor_msgs::LaserScan>("/scan_relayed", 10);
    scan_sub_ = nh.subscribe("/scan", 10, &ScanRelay::onScan, this);
    joint_sub_ = nh.subscribe("/joint_states", 10, &ScanRelay::onJoints, this);
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan)
  {
    sensor_msgs::LaserScan out = *scan;
    try
    {
      const geometry_msgs::TransformStamped t =
          buffer_.lookupTransform("odom", scan->header.frame_id, ros::Time(0));
      out.header.frame_id = t.header.frame_id;
    }
    catch (const tf2::TransformException&)
    {
      return;
    }
    if (!last_joints_.name.empty())
    {
      out.header.seq = last_joints_.header.seq;
    }
    relayed_pub_.publish(out);
  }

  void onJoints(const sensor_msgs::JointState::ConstPtr& joints)
  {
    last_joints_ = *joints;
  }

private:
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
  ros::Publisher relayed_pub_;
  ros::Subscriber scan_sub_;
  ros::Subscriber joint_sub_;
  sensor_msgs::JointState last_joints_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "scan_relay");
  ros::NodeHandle nh;
  ScanRelay node(nh);
  ros::spin();
  return 0;
}
