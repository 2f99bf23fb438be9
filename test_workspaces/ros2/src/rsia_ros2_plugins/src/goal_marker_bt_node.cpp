// A behavior-tree node for navigation2's bt_navigator: the navigator ticks
// the tree from its own loop (bt_loop_duration), so the marker published on
// each tick keeps that rate, whatever rate the goal updates it also listens
// to come at (host_periodic).
#include <memory>
#include <string>

#include "behaviortree_cpp/action_node.h"
#include "behaviortree_cpp/bt_factory.h"
#include "geometry_msgs/msg/pose_stamped.hpp"
#include "rclcpp/rclcpp.hpp"
#include "visualization_msgs/msg/marker.hpp"

namespace rsia_ros2_plugins
{

class GoalMarker : public BT::SyncActionNode
{
public:
  GoalMarker(const std::string & name, const BT::NodeConfiguration & config)
  : BT::SyncActionNode(name, config)
  {
    node_ = config.blackboard->get<rclcpp::Node::SharedPtr>("node");
    marker_pub_ = node_->create_publisher<visualization_msgs::msg::Marker>("goal_marker", 1);
    goal_sub_ = node_->create_subscription<geometry_msgs::msg::PoseStamped>(
      "goal_update", 1,
      [this](const geometry_msgs::msg::PoseStamped::SharedPtr msg) {latest_goal_ = *msg;});
  }

  static BT::PortsList providedPorts()
  {
    return {};
  }

  BT::NodeStatus tick() override
  {
    visualization_msgs::msg::Marker marker;
    marker.pose = latest_goal_.pose;
    marker_pub_->publish(marker);
    return BT::NodeStatus::SUCCESS;
  }

private:
  rclcpp::Node::SharedPtr node_;
  geometry_msgs::msg::PoseStamped latest_goal_;
  rclcpp::Publisher<visualization_msgs::msg::Marker>::SharedPtr marker_pub_;
  rclcpp::Subscription<geometry_msgs::msg::PoseStamped>::SharedPtr goal_sub_;
};

}  // namespace rsia_ros2_plugins

BT_REGISTER_NODES(factory)
{
  factory.registerNodeType<rsia_ros2_plugins::GoalMarker>("GoalMarker");
}
