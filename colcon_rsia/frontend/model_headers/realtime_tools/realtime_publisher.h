// colcon-rsia model of <realtime_tools/realtime_publisher.h> (ROS 1): the
// constructor (or init) advertises the topic given as its second argument;
// unlockAndPublish is the publish site.
#ifndef RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER_H
#define RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER_H

#include <memory>
#include <string>

#include <boost/shared_ptr.hpp>
#include <ros/node_handle.h>

namespace realtime_tools
{

template <class Msg>
class RealtimePublisher
{
public:
  Msg msg_;

  RealtimePublisher(const ros::NodeHandle& node, const std::string& topic, int queue_size,
                    bool latched = false);
  RealtimePublisher();
  ~RealtimePublisher();
  RealtimePublisher(const RealtimePublisher&) = delete;
  RealtimePublisher& operator=(const RealtimePublisher&) = delete;

  void init(const ros::NodeHandle& node, const std::string& topic, int queue_size, bool latched = false);
  void stop();
  bool trylock();
  void unlockAndPublish();
  void lock();
  void unlock();
};

template <class Msg>
using RealtimePublisherSharedPtr = std::shared_ptr<RealtimePublisher<Msg>>;

}  // namespace realtime_tools

#endif  // RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER_H
