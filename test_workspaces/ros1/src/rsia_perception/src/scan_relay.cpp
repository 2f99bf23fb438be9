// scan_relay: clips a laser scan to a maximum range and republishes it.
//
// RSIA pattern covered here: RELAY. The only publish site is inside the subscriber callback,
// so the output rate follows the input rate -> dependent.
// API covered: ros::NodeHandle::subscribe with a FREE FUNCTION callback.
#include <algorithm>
#include <limits>

#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

namespace
{
ros::Publisher g_filtered_pub;
double g_max_range = 8.0;
}  // namespace

// Subscriber callback (free function).
void onScan(const sensor_msgs::LaserScan::ConstPtr& scan)
{
  sensor_msgs::LaserScan out = *scan;
  out.range_max = static_cast<float>(std::min<double>(scan->range_max, g_max_range));
  for (float& r : out.ranges)
  {
    if (r > out.range_max)
    {
      r = std::numeric_limits<float>::infinity();
    }
  }
  // EXPECT scan_filtered: dependent, none (published from a subscriber callback: one output
  // per input message).
  g_filtered_pub.publish(out);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "scan_relay");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  pnh.param("max_range", g_max_range, 8.0);

  g_filtered_pub = nh.advertise<sensor_msgs::LaserScan>("scan_filtered", 10);
  // API: ros::NodeHandle::subscribe, free-function callback.
  ros::Subscriber scan_sub = nh.subscribe("scan", 10, onScan);

  ros::spin();
  return 0;
}
