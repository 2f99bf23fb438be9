// decimator: publishes every 3rd /image (a constant) on /image_third.
// EXPECT /image_third: dependent; triggers [/image], every 3rd message.
// EXPECT rate /image_third: /image / 3 = 10 Hz.
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

namespace
{
constexpr int kEvery = 3;
ros::Publisher g_third_pub;
unsigned int g_count = 0;
}  // namespace

void onImage(const sensor_msgs::Image::ConstPtr& image)
{
  if (++g_count % kEvery == 0)
  {
    g_third_pub.publish(*image);
  }
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "decimator");
  ros::NodeHandle nh;
  g_third_pub = nh.advertise<sensor_msgs::Image>("/image_third", 5);
  ros::Subscriber sub = nh.subscribe("/image", 5, onImage);
  ros::spin();
  return 0;
}
