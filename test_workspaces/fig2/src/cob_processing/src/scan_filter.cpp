// Filters `input` and publishes the result from the subscriber callback
// (dependent). The output topic name is the private parameter ~topic, default
// "filtered"; it is advertised through the default (namespace) NodeHandle, so
// a relative value resolves in the node's namespace, not under its private name.
#include <ros/ros.h>
#include <std_msgs/Header.h>
#include <string>

class ScanFilter
{
public:
  ScanFilter(ros::NodeHandle& nh, ros::NodeHandle& pnh)
  {
    std::string topic;
    pnh.param<std::string>("topic", topic, "filtered");
    filtered_pub_ = nh.advertise<std_msgs::Header>(topic, 5);
    input_sub_ = nh.subscribe("input", 5, &ScanFilter::onScan, this);
  }

private:
  void onScan(const std_msgs::Header::ConstPtr& scan)
  {
    if (scan->frame_id.empty())
      return;  // drop scans without a frame
    filtered_pub_.publish(*scan);
  }

  ros::Publisher filtered_pub_;
  ros::Subscriber input_sub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "scan_filter");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  ScanFilter filter(nh, pnh);
  ros::spin();
  return 0;
}
