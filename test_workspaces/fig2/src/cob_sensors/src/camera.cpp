// Camera driver. No subscribers (pattern 1: independent); frames come from a
// 15 Hz timer. Publishes the relative topic `image`.
#include <ros/ros.h>
#include <std_msgs/Header.h>

class Camera
{
public:
  explicit Camera(ros::NodeHandle& nh)
  {
    image_pub_ = nh.advertise<std_msgs::Header>("image", 2);
    frame_timer_ = nh.createTimer(ros::Duration(1.0 / 15.0), &Camera::onFrame, this);
  }

private:
  void onFrame(const ros::TimerEvent&)
  {
    std_msgs::Header frame;
    frame.stamp = ros::Time::now();
    frame.frame_id = "camera";
    image_pub_.publish(frame);
  }

  ros::Publisher image_pub_;
  ros::Timer frame_timer_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "camera");
  ros::NodeHandle nh;
  Camera camera(nh);
  ros::spin();
  return 0;
}
