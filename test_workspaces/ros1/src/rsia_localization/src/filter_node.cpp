// The members of FilterNode<Algorithm>, instantiated at the end for both
// algorithms: what ekf_node and ukf_node run.
#include "rsia_localization/filter_node.h"

namespace rsia_localization
{

template <typename Algorithm>
FilterNode<Algorithm>::FilterNode(ros::NodeHandle nh, ros::NodeHandle nh_priv)
  : nh_(nh), nh_priv_(nh_priv)
{
}

template <typename Algorithm>
void FilterNode<Algorithm>::initialize()
{
  filtered_pub_ = nh_.advertise<geometry_msgs::PoseStamped>("pose/filtered", 20);
  twist_sub_ = nh_.subscribe("twist", 10, &FilterNode<Algorithm>::twistCallback, this);
  set_pose_sub_ = nh_priv_.subscribe("set_pose", 1, &FilterNode<Algorithm>::setPoseCallback, this);
  update_timer_ = nh_.createTimer(ros::Duration(1.0 / 30.0), &FilterNode<Algorithm>::periodicUpdate, this);
}

template <typename Algorithm>
void FilterNode<Algorithm>::twistCallback(const geometry_msgs::TwistStamped::ConstPtr& msg)
{
  twist_ = *msg;
}

template <typename Algorithm>
void FilterNode<Algorithm>::setPoseCallback(
  const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg)
{
  pose_.pose = msg->pose.pose;
}

template <typename Algorithm>
void FilterNode<Algorithm>::periodicUpdate(const ros::TimerEvent&)
{
  pose_.pose.position.x += algorithm_.gain() * twist_.twist.linear.x;
  filtered_pub_.publish(pose_);
}

template class FilterNode<Ekf>;
template class FilterNode<Ukf>;

}  // namespace rsia_localization
