// A process that loads the driver nodelet itself, under the name
// /front/driver.
#include <nodelet/loader.h>
#include <ros/ros.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "front_manager");
  nodelet::Loader loader;
  nodelet::M_string remappings;
  nodelet::V_string my_argv;
  loader.load("/front/driver", "rsia_hosted_nodelets/DriverNodelet", remappings, my_argv);
  ros::spin();
  return 0;
}
