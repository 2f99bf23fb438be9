#ifndef RSIA_HOSTED_NODELETS_DRIVER_H
#define RSIA_HOSTED_NODELETS_DRIVER_H

#include <ros/ros.h>

namespace rsia_hosted_nodelets
{

// Polls a device and publishes what it reads; no input.
class Driver
{
public:
  Driver(ros::NodeHandle nh, ros::NodeHandle pnh);
  bool poll();

private:
  ros::Publisher packets_pub_;
  ros::Publisher status_pub_;
};

}  // namespace rsia_hosted_nodelets

#endif
