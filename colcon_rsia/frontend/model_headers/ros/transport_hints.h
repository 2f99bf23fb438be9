// colcon-rsia model of <ros/transport_hints.h>.
#ifndef RSIA_MODEL_ROS_TRANSPORT_HINTS_H
#define RSIA_MODEL_ROS_TRANSPORT_HINTS_H

#include <string>
#include <vector>

#include <ros/datatypes.h>

namespace ros
{

class TransportHints
{
public:
  TransportHints& reliable();
  TransportHints& tcp();
  TransportHints& tcpNoDelay(bool nodelay = true);
  bool getTCPNoDelay();
  TransportHints& maxDatagramSize(int size);
  int getMaxDatagramSize();
  TransportHints& unreliable();
  TransportHints& udp();
  std::vector<std::string> getTransports();
  M_string getOptions();
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_TRANSPORT_HINTS_H
