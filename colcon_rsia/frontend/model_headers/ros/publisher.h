// colcon-rsia model of <ros/publisher.h>: ros::Publisher::publish (publish
// site), with its two overloads (shared pointer, reference).
#ifndef RSIA_MODEL_ROS_PUBLISHER_H
#define RSIA_MODEL_ROS_PUBLISHER_H

#include <cstdint>
#include <string>
#include <vector>

#include <boost/shared_ptr.hpp>
#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

class Publisher
{
public:
  Publisher();
  Publisher(const Publisher& rhs);
  ~Publisher();
  Publisher& operator=(const Publisher& other) = default;

  template <typename M>
  void publish(const boost::shared_ptr<M>& message) const;
  template <typename M>
  void publish(const M& message) const;

  void shutdown();
  std::string getTopic() const;
  uint32_t getNumSubscribers() const;
  bool isLatched() const;
  operator void*() const;
  bool operator<(const Publisher& rhs) const;
  bool operator==(const Publisher& rhs) const;
  bool operator!=(const Publisher& rhs) const;
};

typedef std::vector<Publisher> V_Publisher;

}  // namespace ros

#endif  // RSIA_MODEL_ROS_PUBLISHER_H
