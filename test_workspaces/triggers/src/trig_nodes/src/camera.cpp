// camera: publishes /image from a timer of period 1/30 s (no inputs).
// EXPECT rate /image: 30 Hz (timer).
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

ros::Publisher g_image_pub;

void onFrame(const ros::TimerEvent&)
{
  sensor_msgs::Image image;
  image.header.stamp = ros::Time::now();
  g_image_pub.publish(image);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "camera");
  ros::NodeHandle nh;
  g_image_pub = nh.advertise<sensor_msgs::Image>("/image", 5);
  ros::Timer timer = nh.createTimer(ros::Duration(1.0 / 30.0), onFrame);
  ros::spin();
  return 0;
}
