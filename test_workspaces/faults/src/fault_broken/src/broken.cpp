// Does not compile: the build of this package fails with or without rsia.
#include <ros/ros.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "broken");
  this is not C++;
}
