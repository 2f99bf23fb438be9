// Reads `input` in a callback, publishes `output` from main's loop paced by a
// 20 Hz ros::Rate (independent, rate_loop).
#include <ros/ros.h>
#include <std_msgs/Header.h>

static std_msgs::Header g_latest;

static void onInput(const std_msgs::Header::ConstPtr& msg)
{
  g_latest = *msg;
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "rate_loop_node");
  ros::NodeHandle nh;
  ros::Publisher output_pub = nh.advertise<std_msgs::Header>("output", 10);
  ros::Subscriber input_sub = nh.subscribe("input", 10, onInput);

  ros::Rate loop_rate(20);
  while (ros::ok())
  {
    ros::spinOnce();
    std_msgs::Header out = g_latest;
    out.stamp = ros::Time::now();
    output_pub.publish(out);
    loop_rate.sleep();
  }
  return 0;
}
