// colcon-rsia model of <ros/this_node.h>.
#ifndef RSIA_MODEL_ROS_THIS_NODE_H
#define RSIA_MODEL_ROS_THIS_NODE_H

#include <string>

#include <ros/forwards.h>

namespace ros
{

namespace this_node
{

const std::string& getName();
const std::string& getNamespace();
void getAdvertisedTopics(V_string& topics);
void getSubscribedTopics(V_string& topics);

}  // namespace this_node

}  // namespace ros

#endif  // RSIA_MODEL_ROS_THIS_NODE_H
