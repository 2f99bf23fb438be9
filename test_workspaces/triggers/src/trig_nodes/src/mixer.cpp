// mixer: both the /scan and the /joint_states callbacks call report(), which publishes
// /status.
// EXPECT /status: dependent; triggers [/joint_states, /scan].
// EXPECT rate /status: at most the sum, /scan 10 + /joint_states 100 = 110 Hz.
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>

ros::Publisher g_status_pub;

void report(const std::string& what)
{
  std_msgs::String status;
  status.data = what;
  g_status_pub.publish(status);
}

void onScan(const sensor_msgs::LaserScan::ConstPtr&)
{
  report("scan");
}

void onJoints(const sensor_msgs::JointState::ConstPtr&)
{
  report("joints");
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "mixer");
  ros::NodeHandle nh;
  g_status_pub = nh.advertise<std_msgs::String>("/status", 10);
  ros::Subscriber scan_sub = nh.subscribe("/scan", 10, onScan);
  ros::Subscriber joint_sub = nh.subscribe("/joint_states", 10, onJoints);
  ros::spin();
  return 0;
}
