// colcon-rsia model of <tf2_ros/transform_listener.h>: every object subscribes
// to /tf and /tf_static.
#ifndef RSIA_MODEL_TF2_ROS_TRANSFORM_LISTENER_H
#define RSIA_MODEL_TF2_ROS_TRANSFORM_LISTENER_H

// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
#ifdef RSIA_MODEL_RCLCPP
#include <memory>
#include <string>

#include <tf2_ros/buffer.h>
#include <tf2_ros/qos.hpp>

namespace tf2_ros
{

// the buffer is a tf2::BufferCore in the real class (a tf2_ros::Buffer in
// user code); the node forms subscribe /tf and /tf_static on that node, the
// first form on a node of its own
class TransformListener
{
public:
  explicit TransformListener(Buffer & buffer, bool spin_thread = true);
  template<class NodeT, class AllocatorT = std::allocator<void>>
  TransformListener(
    Buffer & buffer, NodeT && node, bool spin_thread = true,
    const rclcpp::QoS & qos = DynamicListenerQoS(),
    const rclcpp::QoS & static_qos = StaticListenerQoS(),
    const rclcpp::SubscriptionOptionsWithAllocator<AllocatorT> & options =
    rclcpp::SubscriptionOptionsWithAllocator<AllocatorT>(),
    const rclcpp::SubscriptionOptionsWithAllocator<AllocatorT> & static_options =
    rclcpp::SubscriptionOptionsWithAllocator<AllocatorT>());
  virtual ~TransformListener();
};

}  // namespace tf2_ros
#else  // ROS 1

#include <boost/thread.hpp>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>

namespace tf2_ros
{

class TransformListener
{
public:
  TransformListener(tf2::BufferCore& buffer, bool spin_thread = true,
                    ros::TransportHints transport_hints = ros::TransportHints());
  TransformListener(tf2::BufferCore& buffer, const ros::NodeHandle& nh, bool spin_thread = true,
                    ros::TransportHints transport_hints = ros::TransportHints());
  ~TransformListener();
};

}  // namespace tf2_ros

#endif  // RSIA_MODEL_RCLCPP

#endif  // RSIA_MODEL_TF2_ROS_TRANSFORM_LISTENER_H
