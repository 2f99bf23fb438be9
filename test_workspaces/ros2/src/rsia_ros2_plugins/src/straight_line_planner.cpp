// A navigation2 global planner: the planner server calls createPlan() when
// a ComputePathToPose request reaches it. The preview it publishes there
// follows the requests (dependent), although the plugin subscribes to
// nothing.
#include <memory>
#include <string>

#include "geometry_msgs/msg/pose_stamped.hpp"
#include "nav2_core/global_planner.hpp"
#include "nav_msgs/msg/path.hpp"
#include "pluginlib/class_list_macros.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"

namespace rsia_ros2_plugins
{

class StraightLinePlanner : public nav2_core::GlobalPlanner
{
public:
  void configure(
    const rclcpp_lifecycle::LifecycleNode::WeakPtr & parent, std::string name,
    std::shared_ptr<tf2_ros::Buffer>, std::shared_ptr<nav2_costmap_2d::Costmap2DROS>) override
  {
    auto node = parent.lock();
    name_ = name;
    preview_pub_ = node->create_publisher<nav_msgs::msg::Path>("plan_preview", 1);
  }

  void cleanup() override {}
  void activate() override {}
  void deactivate() override {}

  nav_msgs::msg::Path createPlan(
    const geometry_msgs::msg::PoseStamped & start,
    const geometry_msgs::msg::PoseStamped & goal,
    std::function<bool()>) override
  {
    nav_msgs::msg::Path path;
    path.poses.push_back(start);
    path.poses.push_back(goal);
    preview_pub_->publish(path);
    return path;
  }

private:
  std::string name_;
  rclcpp::Publisher<nav_msgs::msg::Path>::SharedPtr preview_pub_;
};

}  // namespace rsia_ros2_plugins

PLUGINLIB_EXPORT_CLASS(rsia_ros2_plugins::StraightLinePlanner, nav2_core::GlobalPlanner)
