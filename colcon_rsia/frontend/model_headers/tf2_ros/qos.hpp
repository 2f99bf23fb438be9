// colcon-rsia model of <tf2_ros/qos.hpp> (ROS 2): the default QoS of the tf
// listeners and broadcasters.
#ifndef RSIA_MODEL_TF2_ROS_QOS_HPP
#define RSIA_MODEL_TF2_ROS_QOS_HPP

#include <cstddef>

#include <rclcpp/rclcpp.hpp>

namespace tf2_ros
{

class DynamicListenerQoS : public rclcpp::QoS
{
public:
  explicit DynamicListenerQoS(size_t depth = 100);
};

class StaticListenerQoS : public rclcpp::QoS
{
public:
  explicit StaticListenerQoS(size_t depth = 100);
};

class DynamicBroadcasterQoS : public rclcpp::QoS
{
public:
  explicit DynamicBroadcasterQoS(size_t depth = 100);
};

class StaticBroadcasterQoS : public rclcpp::QoS
{
public:
  explicit StaticBroadcasterQoS(size_t depth = 1);
};

}  // namespace tf2_ros

#endif  // RSIA_MODEL_TF2_ROS_QOS_HPP
