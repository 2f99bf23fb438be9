// colcon-rsia model of <ros/master.h>.
#ifndef RSIA_MODEL_ROS_MASTER_H
#define RSIA_MODEL_ROS_MASTER_H

#include <cstdint>
#include <string>
#include <vector>

#include <ros/forwards.h>

namespace ros
{

namespace master
{

const std::string& getHost();
uint32_t getPort();
const std::string& getURI();
bool check();

struct TopicInfo
{
  TopicInfo();
  TopicInfo(const std::string& _name, const std::string& _datatype);
  std::string name;
  std::string datatype;
};
typedef std::vector<TopicInfo> V_TopicInfo;

bool getTopics(V_TopicInfo& topics);
bool getNodes(V_string& nodes);
void setRetryTimeout(ros::WallDuration timeout);

}  // namespace master

}  // namespace ros

#endif  // RSIA_MODEL_ROS_MASTER_H
