// System monitor: watches /filter_stats, /plan, /odom and /base_status and
// logs a health summary every 2 s. It publishes nothing (leaf node).
#include <string>
#include <ros/ros.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <std_msgs/String.h>
#include <std_msgs/UInt32.h>

class SystemMonitor
{
public:
  explicit SystemMonitor(ros::NodeHandle& nh)
    : scans_filtered_(0), plans_(0), odom_msgs_(0), status_msgs_(0)
  {
    stats_sub_ = nh.subscribe("filter_stats", 1, &SystemMonitor::statsCallback, this);
    plan_sub_ = nh.subscribe("plan", 1, &SystemMonitor::planCallback, this);
    odom_sub_ = nh.subscribe("odom", 10, &SystemMonitor::odomCallback, this);
    status_sub_ = nh.subscribe("base_status", 10, &SystemMonitor::statusCallback, this);
    report_timer_ = nh.createTimer(ros::Duration(2.0), &SystemMonitor::onReportTimer, this);
  }

private:
  void statsCallback(const std_msgs::UInt32::ConstPtr& msg) { scans_filtered_ = msg->data; }
  void planCallback(const geometry_msgs::PoseArray::ConstPtr&) { ++plans_; }
  void odomCallback(const geometry_msgs::PoseStamped::ConstPtr&) { ++odom_msgs_; }
  void statusCallback(const std_msgs::String::ConstPtr& msg)
  {
    ++status_msgs_;
    last_status_ = msg->data;
  }

  void onReportTimer(const ros::TimerEvent&)
  {
    ROS_INFO("monitor: filtered=%u plans=%u odom=%u status=%u last='%s'", scans_filtered_, plans_,
             odom_msgs_, status_msgs_, last_status_.c_str());
  }

  ros::Subscriber stats_sub_;
  ros::Subscriber plan_sub_;
  ros::Subscriber odom_sub_;
  ros::Subscriber status_sub_;
  ros::Timer report_timer_;
  unsigned int scans_filtered_;
  unsigned int plans_;
  unsigned int odom_msgs_;
  unsigned int status_msgs_;
  std::string last_status_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "system_monitor");
  ros::NodeHandle nh;
  SystemMonitor monitor(nh);
  ros::spin();
  return 0;
}
