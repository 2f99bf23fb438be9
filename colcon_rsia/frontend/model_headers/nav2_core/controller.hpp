// colcon-rsia model of <nav2_core/controller.hpp> (navigation2): the
// interface of a controller plugin, written from its documentation
// (docs.nav2.org, "Writing a New Controller Plugin"). The controller server
// calls computeVelocityCommands() at controller_frequency while it follows
// a path.
#ifndef RSIA_MODEL_NAV2_CORE_CONTROLLER_HPP
#define RSIA_MODEL_NAV2_CORE_CONTROLLER_HPP

#include <memory>
#include <string>

#include <geometry_msgs/msg/pose_stamped.hpp>
#include <geometry_msgs/msg/twist.hpp>
#include <geometry_msgs/msg/twist_stamped.hpp>
#include <nav2_core/plugin_context.hpp>
#include <nav_msgs/msg/path.hpp>

namespace nav2_core
{

class GoalChecker;

class Controller
{
public:
  using Ptr = std::shared_ptr<Controller>;
  virtual ~Controller() {}
  virtual void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name,
    std::shared_ptr<tf2_ros::Buffer> tf,
    std::shared_ptr<nav2_costmap_2d::Costmap2DROS> costmap_ros) = 0;
  virtual void cleanup() = 0;
  virtual void activate() = 0;
  virtual void deactivate() = 0;
  virtual void setPlan(const nav_msgs::msg::Path & path) = 0;
  virtual geometry_msgs::msg::TwistStamped computeVelocityCommands(
    const geometry_msgs::msg::PoseStamped & pose,
    const geometry_msgs::msg::Twist & velocity,
    nav2_core::GoalChecker * goal_checker) = 0;
  virtual bool cancel();
  virtual void setSpeedLimit(const double & speed_limit, const bool & percentage) = 0;
  virtual void reset();
};

}  // namespace nav2_core

#endif  // RSIA_MODEL_NAV2_CORE_CONTROLLER_HPP
