// A sensor-like node: no subscribers, so `chatter` is independent.
#include <ros/ros.h>
#include <std_msgs/String.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "talker");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::String>("chatter", 1);
  ros::Rate rate(2);
  while (ros::ok())
  {
    pub.publish(std_msgs::String());
    rate.sleep();
  }
  return 0;
}
