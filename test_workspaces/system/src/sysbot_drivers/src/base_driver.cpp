// Mobile base driver. Accepts velocity commands on /cmd_vel and acknowledges
// each one on /base_status from the subscriber callback (rate follows /cmd_vel).
// Wheel odometry is integrated and published on /odom by publishOdometry(),
// which is only called from the 50 Hz ros::Rate loop in main.
// Expected: /odom independent (rate_loop, 50 Hz), /base_status dependent (none).
#include <cmath>
#include <sstream>
#include <ros/ros.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <std_msgs/String.h>

class BaseDriver
{
public:
  explicit BaseDriver(ros::NodeHandle& nh) : x_(0.0), y_(0.0), yaw_(0.0)
  {
    odom_pub_ = nh.advertise<geometry_msgs::PoseStamped>("odom", 50);
    status_pub_ = nh.advertise<std_msgs::String>("base_status", 10);
    cmd_sub_ = nh.subscribe("cmd_vel", 1, &BaseDriver::cmdVelCallback, this);
    last_update_ = ros::Time::now();
  }

  void publishOdometry()
  {
    const ros::Time now = ros::Time::now();
    const double dt = (now - last_update_).toSec();
    last_update_ = now;

    yaw_ += cmd_.angular.z * dt;
    x_ += cmd_.linear.x * std::cos(yaw_) * dt;
    y_ += cmd_.linear.x * std::sin(yaw_) * dt;

    geometry_msgs::PoseStamped odom;
    odom.header.stamp = now;
    odom.header.frame_id = "odom";
    odom.pose.position.x = x_;
    odom.pose.position.y = y_;
    odom.pose.orientation.z = std::sin(yaw_ / 2.0);
    odom.pose.orientation.w = std::cos(yaw_ / 2.0);
    odom_pub_.publish(odom);
  }

private:
  void cmdVelCallback(const geometry_msgs::Twist::ConstPtr& msg)
  {
    cmd_ = *msg;
    std_msgs::String status;
    std::ostringstream ss;
    ss << "cmd accepted: v=" << cmd_.linear.x << " w=" << cmd_.angular.z;
    status.data = ss.str();
    status_pub_.publish(status);
  }

  ros::Publisher odom_pub_;
  ros::Publisher status_pub_;
  ros::Subscriber cmd_sub_;
  geometry_msgs::Twist cmd_;
  ros::Time last_update_;
  double x_;
  double y_;
  double yaw_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "base_driver");
  ros::NodeHandle nh;
  BaseDriver driver(nh);

  ros::Rate loop_rate(50.0);
  while (ros::ok())
  {
    ros::spinOnce();
    driver.publishOdometry();
    loop_rate.sleep();
  }
  return 0;
}
