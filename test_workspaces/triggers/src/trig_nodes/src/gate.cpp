// gate: /enable only sets a flag (shared state); the /image callback publishes /gated while
// the flag is set.
// EXPECT /gated: dependent; triggers [/image]. The trigger model's documented miss: /enable
// gates /gated through shared state (when /enable stops, /gated stops) yet is no trigger.
// EXPECT rate /gated: follows /image = 30 Hz (an upper bound: the gate may hold it back).
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Bool.h>

class Gate
{
public:
  explicit Gate(ros::NodeHandle& nh)
  {
    gated_pub_ = nh.advertise<sensor_msgs::Image>("/gated", 5);
    enable_sub_ = nh.subscribe("/enable", 1, &Gate::onEnable, this);
    image_sub_ = nh.subscribe("/image", 5, &Gate::onImage, this);
  }

  void onEnable(const std_msgs::Bool::ConstPtr& enable)
  {
    enabled_ = enable->data;
  }

  void onImage(const sensor_msgs::Image::ConstPtr& image)
  {
    if (enabled_)
    {
      gated_pub_.publish(*image);
    }
  }

private:
  bool enabled_ = false;
  ros::Publisher gated_pub_;
  ros::Subscriber enable_sub_;
  ros::Subscriber image_sub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "gate");
  ros::NodeHandle nh;
  Gate node(nh);
  ros::spin();
  return 0;
}
