// Consumes `input` and publishes nothing (a leaf of the dependency graph).
#include <ros/ros.h>
#include <std_msgs/Header.h>

static unsigned long g_received = 0;

static void onInput(const std_msgs::Header::ConstPtr&)
{
  ++g_received;
  ROS_DEBUG_THROTTLE(10.0, "received %lu messages", g_received);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "sink");
  ros::NodeHandle nh;
  ros::Subscriber sub = nh.subscribe("input", 10, onInput);
  ros::spin();
  return 0;
}
