#include <rsia_hosted_nodelets/driver.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "driver");
  rsia_hosted_nodelets::Driver driver(ros::NodeHandle(), ros::NodeHandle("~"));
  while (ros::ok() && driver.poll())
  {
    ros::spinOnce();
  }
  return 0;
}
