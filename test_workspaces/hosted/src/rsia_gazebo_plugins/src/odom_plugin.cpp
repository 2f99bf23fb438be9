// A model plugin: its NodeHandle lives in the namespace the SDF gives
// (robotNamespace), which only the world or robot description knows.
#include <boost/bind.hpp>
#include <gazebo/common/Events.hh>
#include <gazebo/common/Plugin.hh>
#include <gazebo/physics/physics.hh>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf/transform_broadcaster.h>

namespace gazebo
{

class OdomPlugin : public ModelPlugin
{
public:
  void Load(physics::ModelPtr model, sdf::ElementPtr sdf) override
  {
    robot_namespace_ = sdf->Get<std::string>("robotNamespace");
    rosnode_.reset(new ros::NodeHandle(robot_namespace_));
    odom_pub_ = rosnode_->advertise<nav_msgs::Odometry>("odom", 1);
    cmd_sub_ = rosnode_->subscribe("cmd_vel", 1, &OdomPlugin::OnCmdVel, this);
    update_connection_ = event::Events::ConnectWorldUpdateBegin(
      boost::bind(&OdomPlugin::OnUpdate, this));
  }

  void OnCmdVel(const geometry_msgs::Twist::ConstPtr& cmd)
  {
    speed_ = cmd->linear.x;
  }

  void OnUpdate()
  {
    nav_msgs::Odometry odom;
    odom.twist.twist.linear.x = speed_;
    odom_pub_.publish(odom);
    tf::StampedTransform transform;
    broadcaster_.sendTransform(transform);
  }

private:
  std::string robot_namespace_;
  boost::shared_ptr<ros::NodeHandle> rosnode_;
  ros::Publisher odom_pub_;
  ros::Subscriber cmd_sub_;
  tf::TransformBroadcaster broadcaster_;
  event::ConnectionPtr update_connection_;
  double speed_ = 0.0;
};

GZ_REGISTER_MODEL_PLUGIN(OdomPlugin)

}  // namespace gazebo
