// colcon-rsia model of <nav2_core/global_planner.hpp> (navigation2): the
// interface of a planner plugin, written from its documentation
// (docs.nav2.org, "Writing a New Planner Plugin"). The planner server calls
// createPlan() for each path request.
#ifndef RSIA_MODEL_NAV2_CORE_GLOBAL_PLANNER_HPP
#define RSIA_MODEL_NAV2_CORE_GLOBAL_PLANNER_HPP

#include <functional>
#include <memory>
#include <string>

#include <geometry_msgs/msg/pose_stamped.hpp>
#include <nav2_core/plugin_context.hpp>
#include <nav_msgs/msg/path.hpp>

namespace nav2_core
{

class GlobalPlanner
{
public:
  using Ptr = std::shared_ptr<GlobalPlanner>;
  virtual ~GlobalPlanner() {}
  virtual void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name,
    std::shared_ptr<tf2_ros::Buffer> tf,
    std::shared_ptr<nav2_costmap_2d::Costmap2DROS> costmap_ros) = 0;
  virtual void cleanup() = 0;
  virtual void activate() = 0;
  virtual void deactivate() = 0;
  virtual nav_msgs::msg::Path createPlan(
    const geometry_msgs::msg::PoseStamped & start,
    const geometry_msgs::msg::PoseStamped & goal,
    std::function<bool()> cancel_checker) = 0;
};

}  // namespace nav2_core

#endif  // RSIA_MODEL_NAV2_CORE_GLOBAL_PLANNER_HPP
