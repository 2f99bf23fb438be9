// Republishes every message received on `input` to `output` from the subscriber
// callback: the output rate follows the input rate (dependent).
#include <ros/ros.h>
#include <std_msgs/Header.h>

static ros::Publisher g_output;

static void onInput(const std_msgs::Header::ConstPtr& msg)
{
  g_output.publish(*msg);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "relay");
  ros::NodeHandle nh;
  g_output = nh.advertise<std_msgs::Header>("output", 10);
  ros::Subscriber sub = nh.subscribe("input", 10, onInput);
  ros::spin();
  return 0;
}
