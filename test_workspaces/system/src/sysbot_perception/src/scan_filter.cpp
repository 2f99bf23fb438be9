// Scan filter: clamps out-of-range beams of every incoming /scan and relays the
// result on /scan_filtered from the subscriber callback. Once per second a
// timer reports how many scans were filtered on /filter_stats.
// Expected: /scan_filtered dependent (none), /filter_stats independent (timer, 1 Hz).
#include <limits>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/UInt32.h>

class ScanFilter
{
public:
  explicit ScanFilter(ros::NodeHandle& nh) : filtered_count_(0)
  {
    filtered_pub_ = nh.advertise<sensor_msgs::LaserScan>("scan_filtered", 10);
    stats_pub_ = nh.advertise<std_msgs::UInt32>("filter_stats", 1);
    scan_sub_ = nh.subscribe("scan", 10, &ScanFilter::scanCallback, this);
    stats_timer_ = nh.createTimer(ros::Duration(1.0), &ScanFilter::onStatsTimer, this);
  }

private:
  void scanCallback(const sensor_msgs::LaserScan::ConstPtr& msg)
  {
    sensor_msgs::LaserScan out = *msg;
    for (float& r : out.ranges)
    {
      if (r < out.range_min || r > out.range_max)
      {
        r = std::numeric_limits<float>::infinity();
      }
    }
    ++filtered_count_;
    filtered_pub_.publish(out);
  }

  void onStatsTimer(const ros::TimerEvent&)
  {
    std_msgs::UInt32 stats;
    stats.data = filtered_count_;
    stats_pub_.publish(stats);
  }

  ros::Publisher filtered_pub_;
  ros::Publisher stats_pub_;
  ros::Subscriber scan_sub_;
  ros::Timer stats_timer_;
  unsigned int filtered_count_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "scan_filter");
  ros::NodeHandle nh;
  ScanFilter filter(nh);
  ros::spin();
  return 0;
}
