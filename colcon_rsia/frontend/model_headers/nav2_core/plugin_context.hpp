// colcon-rsia model: what the navigation2 plugin interfaces receive from
// their server (no such header exists in navigation2; the models of
// global_planner.hpp and controller.hpp share it).
#ifndef RSIA_MODEL_NAV2_CORE_PLUGIN_CONTEXT_HPP
#define RSIA_MODEL_NAV2_CORE_PLUGIN_CONTEXT_HPP

#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <tf2_ros/buffer.hpp>

namespace nav2_costmap_2d
{
class Costmap2D;
class Costmap2DROS;
}  // namespace nav2_costmap_2d

#endif  // RSIA_MODEL_NAV2_CORE_PLUGIN_CONTEXT_HPP
