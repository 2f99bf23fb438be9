// A base controller whose control loop runs on a timer made from a
// ros::TimerOptions object (its own callback queue), as a hardware driver
// does to keep the hardware's calls on one thread.
#include <ros/ros.h>
#include <ros/callback_queue.h>
#include <std_msgs/String.h>
#include <geometry_msgs/Twist.h>
#include <boost/bind/bind.hpp>

struct Base
{
  ros::Publisher status;
  double speed = 0.0;
};

void controlLoop(Base & base)
{
  std_msgs::String message;
  base.status.publish(message);
}

void onCommand(Base & base, const geometry_msgs::Twist::ConstPtr & command)
{
  base.speed = command->linear.x;
}

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "base_controller");
  ros::NodeHandle nh;
  Base base;
  base.status = nh.advertise<std_msgs::String>("base_status", 1);
  ros::Subscriber command = nh.subscribe<geometry_msgs::Twist>(
    "cmd_vel", 1, boost::bind(onCommand, boost::ref(base), boost::placeholders::_1));
  ros::CallbackQueue queue;
  ros::AsyncSpinner spinner(1, &queue);
  ros::TimerOptions control(
    ros::Duration(1 / 20.0), boost::bind(controlLoop, boost::ref(base)), &queue);
  ros::Timer loop = nh.createTimer(control);
  spinner.start();
  ros::spin();
  return 0;
}
