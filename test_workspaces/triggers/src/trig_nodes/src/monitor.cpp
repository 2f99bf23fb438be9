// monitor: a sink of every derived topic (publishes nothing).
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>

unsigned int g_seen = 0;

void onScan(const sensor_msgs::LaserScan::ConstPtr&) { ++g_seen; }
void onImage(const sensor_msgs::Image::ConstPtr&) { ++g_seen; }
void onStatus(const std_msgs::String::ConstPtr&) { ++g_seen; }
void onBusy(const std_msgs::Empty::ConstPtr&) { ++g_seen; }

int main(int argc, char** argv)
{
  ros::init(argc, argv, "monitor");
  ros::NodeHandle nh;
  ros::Subscriber fused = nh.subscribe("/fused", 10, onScan);
  ros::Subscriber status = nh.subscribe("/status", 10, onStatus);
  ros::Subscriber gated = nh.subscribe("/gated", 10, onImage);
  ros::Subscriber third = nh.subscribe("/image_third", 10, onImage);
  ros::Subscriber busy = nh.subscribe("/busy", 10, onBusy);
  ros::spin();
  return 0;
}
