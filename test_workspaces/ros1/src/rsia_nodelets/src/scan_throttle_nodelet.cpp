// ScanThrottle nodelet: keeps the newest laser scan and republishes it at a fixed rate.
//
// RSIA patterns covered here:
// - NODELET: the node is the plugin `rsia_nodelets/ScanThrottle` (nodelet_plugins.xml);
//   its root is onInit(); handles come from getNodeHandle() / getPrivateNodeHandle().
// - TIMER with a rate from a parameter: scan_throttled is independent (timer) but its rate is
//   not a constant -> rate_hz null.
// - Publish in the subscriber callback -> dependent.
// API covered: ros::NodeHandle::subscribe with a member function pointer + this.
#include <nodelet/nodelet.h>
// ROS 1 Noetic provides both class_list_macros.h and class_list_macros.hpp; Debian ships only
// the (ROS 2) .hpp spelling, which defines the same PLUGINLIB_EXPORT_CLASS macro.
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/UInt32.h>

namespace rsia_nodelets
{

class ScanThrottleNodelet : public nodelet::Nodelet
{
private:
  void onInit() override
  {
    // API: nodelet::Nodelet::getNodeHandle / getPrivateNodeHandle.
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();

    // Output rate from a parameter: not a compile-time constant.
    double rate_hz = 2.0;
    pnh.param("rate", rate_hz, 2.0);

    throttled_pub_ = nh.advertise<sensor_msgs::LaserScan>("scan_throttled", 1);
    count_pub_ = pnh.advertise<std_msgs::UInt32>("received", 10);

    // API: ros::NodeHandle::subscribe, member function pointer + this.
    scan_sub_ = nh.subscribe("scan", 10, &ScanThrottleNodelet::onScan, this);
    // API: ros::NodeHandle::createTimer, Duration form with a member callback (period from
    // a parameter -> timer rate_hz null).
    timer_ = nh.createTimer(ros::Duration(1.0 / rate_hz), &ScanThrottleNodelet::onTimer, this);
    NODELET_INFO("ScanThrottle: republishing scans at %.2f Hz", rate_hz);
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan)
  {
    latest_ = scan;
    std_msgs::UInt32 count;
    count.data = ++received_;
    // EXPECT received: dependent, none (subscriber callback).
    count_pub_.publish(count);
  }

  void onTimer(const ros::TimerEvent& /*event*/)
  {
    if (!latest_)
    {
      return;
    }
    // EXPECT scan_throttled: independent, timer (only reached from the timer callback),
    // rate_hz null (the period comes from the ~rate parameter).
    throttled_pub_.publish(latest_);
  }

  ros::Publisher throttled_pub_;
  ros::Publisher count_pub_;
  ros::Subscriber scan_sub_;
  ros::Timer timer_;
  sensor_msgs::LaserScan::ConstPtr latest_;
  uint32_t received_ = 0;
};

}  // namespace rsia_nodelets

PLUGINLIB_EXPORT_CLASS(rsia_nodelets::ScanThrottleNodelet, nodelet::Nodelet)
