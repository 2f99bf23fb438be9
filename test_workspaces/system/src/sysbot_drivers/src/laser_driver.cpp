// Laser driver: no subscribers. Publishes a synthetic scan at a fixed 10 Hz
// from a ros::Rate loop in main.
// Expected: /scan independent (no_subscribers).
#include <cmath>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

namespace
{
const int kBeams = 360;

sensor_msgs::LaserScan makeScan(unsigned int seq)
{
  sensor_msgs::LaserScan scan;
  scan.header.seq = seq;
  scan.header.stamp = ros::Time::now();
  scan.header.frame_id = "laser";
  scan.angle_min = -M_PI;
  scan.angle_max = M_PI;
  scan.angle_increment = 2.0 * M_PI / kBeams;
  scan.range_min = 0.05f;
  scan.range_max = 12.0f;
  scan.ranges.resize(kBeams);
  for (int i = 0; i < kBeams; ++i)
  {
    scan.ranges[i] = 2.0f + 0.5f * std::sin(0.1 * i + 0.05 * seq);
  }
  return scan;
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "laser_driver");
  ros::NodeHandle nh;

  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("scan", 10);

  ros::Rate rate(10.0);
  unsigned int seq = 0;
  while (ros::ok())
  {
    scan_pub.publish(makeScan(seq++));
    rate.sleep();
  }
  return 0;
}
