// busy_loop: caches /joint_states and publishes /busy from an unpaced loop in main: which
// input drives /busy cannot be told, so every input triggers it (the paper's rule).
// EXPECT /busy: dependent; triggers "*" (main reaches the publish call unpaced).
// EXPECT rate /busy: unknown.
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Empty.h>

sensor_msgs::JointState g_last;

void onJoints(const sensor_msgs::JointState::ConstPtr& joints)
{
  g_last = *joints;
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "busy_loop");
  ros::NodeHandle nh;
  ros::Publisher busy_pub = nh.advertise<std_msgs::Empty>("/busy", 1);
  ros::Subscriber sub = nh.subscribe("/joint_states", 10, onJoints);
  while (ros::ok())
  {
    ros::spinOnce();
    busy_pub.publish(std_msgs::Empty());
  }
  return 0;
}
