#include <rsia_hosted_nodelets/driver.h>
#include <std_msgs/String.h>
#include <std_msgs/UInt8MultiArray.h>

namespace rsia_hosted_nodelets
{

Driver::Driver(ros::NodeHandle nh, ros::NodeHandle pnh)
{
  packets_pub_ = nh.advertise<std_msgs::UInt8MultiArray>("packets", 10);
  status_pub_ = pnh.advertise<std_msgs::String>("status", 1);
}

bool Driver::poll()
{
  std_msgs::UInt8MultiArray packet;
  packets_pub_.publish(packet);
  std_msgs::String status;
  status_pub_.publish(status);
  return true;
}

}  // namespace rsia_hosted_nodelets
