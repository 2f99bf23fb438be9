// colcon-rsia model of <ros/subscriber.h>.
#ifndef RSIA_MODEL_ROS_SUBSCRIBER_H
#define RSIA_MODEL_ROS_SUBSCRIBER_H

#include <cstdint>
#include <string>
#include <vector>

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

class Subscriber
{
public:
  Subscriber();
  Subscriber(const Subscriber& rhs);
  ~Subscriber();
  Subscriber& operator=(const Subscriber& other) = default;

  void shutdown();
  std::string getTopic() const;
  uint32_t getNumPublishers() const;
  operator void*() const;
  bool operator<(const Subscriber& rhs) const;
  bool operator==(const Subscriber& rhs) const;
  bool operator!=(const Subscriber& rhs) const;
};

typedef std::vector<Subscriber> V_Subscriber;

}  // namespace ros

#endif  // RSIA_MODEL_ROS_SUBSCRIBER_H
