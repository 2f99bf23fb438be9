// colcon-rsia model of <ros/topic.h>: ros::topic::waitForMessage.
#ifndef RSIA_MODEL_ROS_TOPIC_H
#define RSIA_MODEL_ROS_TOPIC_H

#include <string>

#include <boost/shared_ptr.hpp>
#include <ros/common.h>
#include <ros/node_handle.h>

namespace ros
{

namespace topic
{

template <class M>
boost::shared_ptr<M const> waitForMessage(const std::string& topic, NodeHandle& nh, ros::Duration timeout);
template <class M>
boost::shared_ptr<M const> waitForMessage(const std::string& topic);
template <class M>
boost::shared_ptr<M const> waitForMessage(const std::string& topic, ros::Duration timeout);
template <class M>
boost::shared_ptr<M const> waitForMessage(const std::string& topic, ros::NodeHandle& nh);

}  // namespace topic

}  // namespace ros

#endif  // RSIA_MODEL_ROS_TOPIC_H
