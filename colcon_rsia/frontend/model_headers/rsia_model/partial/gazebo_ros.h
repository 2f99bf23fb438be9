// colcon-rsia partial model of gazebo_ros (ROS 2), the bridge between
// Gazebo classic and rclcpp: gazebo_ros::Node, the node a plugin gets from
// Node::Get(sdf), named after the SDF's <plugin name> in the SDF's
// <ros><namespace> (gazebo_ros/node.hpp). The rest of `gazebo_ros::` is
// left to the stand-ins of unknown libraries (see partial/gazebo.h). ROS 1
// has a gazebo_ros package too, without this class: declared only for
// ROS 2 units.
#ifndef RSIA_MODEL_PARTIAL_GAZEBO_ROS_H
#define RSIA_MODEL_PARTIAL_GAZEBO_ROS_H

#include <rsia_model/partial/gazebo.h>

#if defined(RSIA_MODEL_RCLCPP) && !defined(RSIA_REPAIRED__gazebo_ros__Node)
#define RSIA_REPAIRED__gazebo_ros__Node 1

#include <memory>
#include <string>

#include <rclcpp/rclcpp.hpp>

namespace gazebo_ros
{

class Node : public rclcpp::Node
{
public:
  using SharedPtr = std::shared_ptr<Node>;
  // the node of a plugin, from its SDF
  static SharedPtr Get(sdf::ElementPtr sdf);
  static SharedPtr Get(sdf::ElementPtr sdf, std::string node_name);
  // the node gazebo_ros_init made for gzserver itself
  static SharedPtr Get();
  template <typename... Args>
  static SharedPtr CreateWithArgs(Args&&... args);
};

}  // namespace gazebo_ros
#endif

#endif  // RSIA_MODEL_PARTIAL_GAZEBO_ROS_H
