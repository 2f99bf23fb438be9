// colcon-rsia model of <realtime_tools/realtime_publisher.h> (ROS 1): the
// constructor (or init) advertises the topic given as its second argument;
// unlockAndPublish is the publish site.
//
// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
// The ROS 2 class is in <realtime_tools/realtime_publisher.hpp>; both define
// RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER.
#ifdef RSIA_MODEL_RCLCPP
#include <realtime_tools/realtime_publisher.hpp>
#else  // ROS 1
#ifndef RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER
#define RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER

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

#endif  // RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER
#endif  // RSIA_MODEL_RCLCPP
