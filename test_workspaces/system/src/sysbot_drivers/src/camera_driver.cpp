// Camera driver: no subscribers. Grabs a (synthetic) frame every 50 ms from a
// timer callback.
// Expected: /image independent (no_subscribers).
#include <cstdint>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

class CameraDriver
{
public:
  explicit CameraDriver(ros::NodeHandle& nh) : frame_(0)
  {
    image_pub_ = nh.advertise<sensor_msgs::Image>("image", 2);
    grab_timer_ = nh.createTimer(ros::Duration(0.05), &CameraDriver::onGrabTimer, this);
  }

private:
  void onGrabTimer(const ros::TimerEvent&)
  {
    sensor_msgs::Image img;
    img.header.stamp = ros::Time::now();
    img.header.frame_id = "camera";
    img.width = 64;
    img.height = 48;
    img.encoding = "mono8";
    img.step = img.width;
    img.data.assign(img.width * img.height, static_cast<uint8_t>(frame_ % 256));
    ++frame_;
    image_pub_.publish(img);
  }

  ros::Publisher image_pub_;
  ros::Timer grab_timer_;
  unsigned int frame_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "camera_driver");
  ros::NodeHandle nh;
  CameraDriver driver(nh);
  ros::spin();
  return 0;
}
