// Laser scanner driver (Fig. 2's starred node). No subscribers at all, so every
// publisher is rate-independent (pattern 1); the scan is also paced by a 10 Hz
// ros::Rate loop. Publishes the relative topic `scan` on the default NodeHandle:
// /<namespace>/scan unless remapped by the launch file.
#include <ros/ros.h>
#include <std_msgs/Header.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "laser_scanner");
  ros::NodeHandle nh;
  ros::Publisher scan_pub = nh.advertise<std_msgs::Header>("scan", 5);

  std_msgs::Header scan;
  scan.frame_id = "laser";
  ros::Rate rate(10.0);
  while (ros::ok())
  {
    scan.stamp = ros::Time::now();
    ++scan.seq;
    scan_pub.publish(scan);
    ros::spinOnce();
    rate.sleep();
  }
  return 0;
}
