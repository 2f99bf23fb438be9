// enabler: publishes /enable (the gate of /gated) from a 1 Hz timer.
// EXPECT rate /enable: 1 Hz (timer).
#include <ros/ros.h>
#include <std_msgs/Bool.h>

ros::Publisher g_enable_pub;

void onTimer(const ros::TimerEvent&)
{
  std_msgs::Bool enable;
  enable.data = true;
  g_enable_pub.publish(enable);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "enabler");
  ros::NodeHandle nh;
  g_enable_pub = nh.advertise<std_msgs::Bool>("/enable", 1);
  ros::Timer timer = nh.createTimer(ros::Duration(1.0), onTimer);
  ros::spin();
  return 0;
}
