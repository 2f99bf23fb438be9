// lidar: publishes /scan from a 10 Hz Rate loop in main (no inputs).
// EXPECT rate /scan: 10 Hz (Rate loop).
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "lidar");
  ros::NodeHandle nh;
  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("/scan", 10);
  ros::Rate rate(10);
  while (ros::ok())
  {
    sensor_msgs::LaserScan scan;
    scan.header.stamp = ros::Time::now();
    scan_pub.publish(scan);
    rate.sleep();
  }
  return 0;
}
