// Planner: caches the latest /scan_filtered, /obstacles and /odom in their
// callbacks (no publishing there) and replans at a fixed 5 Hz from a timer,
// publishing the waypoints on /plan.
// Expected: /plan independent (timer, 5 Hz).
#include <algorithm>
#include <cmath>
#include <ros/ros.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <sensor_msgs/LaserScan.h>

class Planner
{
public:
  explicit Planner(ros::NodeHandle& nh) : min_range_(10.0), have_odom_(false)
  {
    plan_pub_ = nh.advertise<geometry_msgs::PoseArray>("plan", 1);
    scan_sub_ = nh.subscribe("scan_filtered", 5, &Planner::scanCallback, this);
    obstacle_sub_ = nh.subscribe("obstacles", 5, &Planner::obstacleCallback, this);
    odom_sub_ = nh.subscribe("odom", 20, &Planner::odomCallback, this);
    plan_timer_ = nh.createTimer(ros::Duration(0.2), &Planner::onPlanTimer, this);
  }

private:
  void scanCallback(const sensor_msgs::LaserScan::ConstPtr& scan)
  {
    double closest = scan->range_max;
    for (float r : scan->ranges)
    {
      if (std::isfinite(r) && r < closest)
      {
        closest = r;
      }
    }
    min_range_ = closest;
  }

  void obstacleCallback(const geometry_msgs::PoseArray::ConstPtr& obstacles)
  {
    obstacles_ = *obstacles;
  }

  void odomCallback(const geometry_msgs::PoseStamped::ConstPtr& odom)
  {
    pose_ = *odom;
    have_odom_ = true;
  }

  void onPlanTimer(const ros::TimerEvent&)
  {
    if (!have_odom_)
    {
      return;
    }
    geometry_msgs::PoseArray plan;
    plan.header.stamp = ros::Time::now();
    plan.header.frame_id = "odom";
    const double step = std::min(0.5, 0.5 * min_range_);
    const double lateral = obstacles_.poses.empty() ? 0.0 : 0.3;
    for (int i = 1; i <= 5; ++i)
    {
      geometry_msgs::Pose wp = pose_.pose;
      wp.position.x += i * step;
      wp.position.y += lateral;
      plan.poses.push_back(wp);
    }
    plan_pub_.publish(plan);
  }

  ros::Publisher plan_pub_;
  ros::Subscriber scan_sub_;
  ros::Subscriber obstacle_sub_;
  ros::Subscriber odom_sub_;
  ros::Timer plan_timer_;
  geometry_msgs::PoseArray obstacles_;
  geometry_msgs::PoseStamped pose_;
  double min_range_;
  bool have_odom_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "planner");
  ros::NodeHandle nh;
  Planner planner(nh);
  ros::spin();
  return 0;
}
