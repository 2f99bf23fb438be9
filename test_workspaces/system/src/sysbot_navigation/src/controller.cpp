// Controller: computes a velocity command toward the first waypoint of every
// received /plan and publishes it on /cmd_vel from the subscriber callback.
// Expected: /cmd_vel dependent (none).
#include <algorithm>
#include <cmath>
#include <ros/ros.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/Twist.h>

class Controller
{
public:
  explicit Controller(ros::NodeHandle& nh)
  {
    cmd_pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
    plan_sub_ = nh.subscribe("plan", 1, &Controller::planCallback, this);
  }

private:
  void planCallback(const geometry_msgs::PoseArray::ConstPtr& plan)
  {
    geometry_msgs::Twist cmd;
    if (plan->poses.size() >= 2)
    {
      const geometry_msgs::Point& a = plan->poses[0].position;
      const geometry_msgs::Point& b = plan->poses[1].position;
      const double dx = b.x - a.x;
      const double dy = b.y - a.y;
      cmd.linear.x = std::min(0.8, std::hypot(dx, dy));
      cmd.angular.z = std::max(-1.0, std::min(1.0, 2.0 * std::atan2(dy, dx)));
    }
    cmd_pub_.publish(cmd);
  }

  ros::Publisher cmd_pub_;
  ros::Subscriber plan_sub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "controller");
  ros::NodeHandle nh;
  Controller controller(nh);
  ros::spin();
  return 0;
}
