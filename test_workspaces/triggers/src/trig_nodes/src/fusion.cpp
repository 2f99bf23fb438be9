// fusion: a message_filters synchronizer of /scan_relayed and /image; its callback
// publishes /fused.
// EXPECT /fused: dependent; triggers [/image, /scan_relayed] (both synchronizer inputs).
// EXPECT rate /fused: the slowest input, min(/scan_relayed 10, /image 30) = 10 Hz.
#include <message_filters/subscriber.h>
#include <message_filters/sync_policies/approximate_time.h>
#include <message_filters/synchronizer.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>

class Fusion
{
public:
  using Policy =
      message_filters::sync_policies::ApproximateTime<sensor_msgs::LaserScan, sensor_msgs::Image>;

  explicit Fusion(ros::NodeHandle& nh)
    : scan_sub_(nh, "/scan_relayed", 10), image_sub_(nh, "/image", 10),
      sync_(Policy(10), scan_sub_, image_sub_)
  {
    fused_pub_ = nh.advertise<sensor_msgs::LaserScan>("/fused", 10);
    sync_.registerCallback(&Fusion::onPair, this);
  }

  void onPair(const sensor_msgs::LaserScan::ConstPtr& scan, const sensor_msgs::Image::ConstPtr& image)
  {
    sensor_msgs::LaserScan out = *scan;
    out.header.stamp = image->header.stamp;
    fused_pub_.publish(out);
  }

private:
  message_filters::Subscriber<sensor_msgs::LaserScan> scan_sub_;
  message_filters::Subscriber<sensor_msgs::Image> image_sub_;
  message_filters::Synchronizer<Policy> sync_;
  ros::Publisher fused_pub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "fusion");
  ros::NodeHandle nh;
  Fusion node(nh);
  ros::spin();
  return 0;
}
