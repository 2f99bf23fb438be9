// FilterNode<Algorithm>: one node class, instantiated per estimation
// algorithm (src/filter_node.cpp), each instantiation run by its own
// executable (src/ekf_node.cpp, src/ukf_node.cpp).
#ifndef RSIA_LOCALIZATION_FILTER_NODE_H
#define RSIA_LOCALIZATION_FILTER_NODE_H

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <ros/ros.h>

namespace rsia_localization
{

struct Ekf
{
  double gain() const { return 0.5; }
};

struct Ukf
{
  double gain() const { return 0.3; }
};

template <typename Algorithm>
class FilterNode
{
public:
  FilterNode(ros::NodeHandle nh, ros::NodeHandle nh_priv);

  void initialize();

private:
  void twistCallback(const geometry_msgs::TwistStamped::ConstPtr& msg);
  void setPoseCallback(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg);
  void periodicUpdate(const ros::TimerEvent& event);

  ros::NodeHandle nh_;
  ros::NodeHandle nh_priv_;
  ros::Publisher filtered_pub_;
  ros::Subscriber twist_sub_;
  ros::Subscriber set_pose_sub_;
  ros::Timer update_timer_;
  geometry_msgs::PoseStamped pose_;
  geometry_msgs::TwistStamped twist_;
  Algorithm algorithm_;
};

}  // namespace rsia_localization

#endif  // RSIA_LOCALIZATION_FILTER_NODE_H
