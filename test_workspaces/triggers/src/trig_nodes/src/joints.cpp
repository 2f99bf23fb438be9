// joints: publishes /joint_states from a 100 Hz Rate loop (a hub: three nodes read it).
// EXPECT rate /joint_states: 100 Hz (Rate loop).
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "joints");
  ros::NodeHandle nh;
  ros::Publisher joint_pub = nh.advertise<sensor_msgs::JointState>("/joint_states", 10);
  ros::Rate rate(100.0);
  while (ros::ok())
  {
    sensor_msgs::JointState state;
    state.header.stamp = ros::Time::now();
    joint_pub.publish(state);
    rate.sleep();
  }
  return 0;
}
