// Minimal stand-in for realtime_tools/realtime_publisher.h (ROS 1).
//
// The real class hands the message to a background thread that publishes it, so that a
// real-time loop never blocks on the middleware. This stand-in keeps the public interface
// (constructor, init, trylock, msg_, unlockAndPublish) but publishes synchronously: it
// exists only so that the test workspace compiles on a machine without realtime_tools.
#ifndef REALTIME_TOOLS__REALTIME_PUBLISHER_H_
#define REALTIME_TOOLS__REALTIME_PUBLISHER_H_

#include <memory>
#include <mutex>
#include <string>

#include <ros/ros.h>

namespace realtime_tools
{

template <class Msg>
class RealtimePublisher
{
public:
  /// The message to fill between trylock() and unlockAndPublish().
  Msg msg_;

  RealtimePublisher() = default;

  RealtimePublisher(const ros::NodeHandle& node, const std::string& topic, int queue_size,
                    bool latched = false)
  {
    init(node, topic, queue_size, latched);
  }

  RealtimePublisher(const RealtimePublisher&) = delete;
  RealtimePublisher& operator=(const RealtimePublisher&) = delete;

  void init(const ros::NodeHandle& node, const std::string& topic, int queue_size,
            bool latched = false)
  {
    node_ = node;
    publisher_ = node_.advertise<Msg>(topic, static_cast<uint32_t>(queue_size), latched);
  }

  /// Non-blocking: true when the caller now owns msg_.
  bool trylock() { return mutex_.try_lock(); }

  void lock() { mutex_.lock(); }
  void unlock() { mutex_.unlock(); }

  /// Publishes msg_ and releases the lock taken by trylock()/lock().
  void unlockAndPublish()
  {
    publisher_.publish(msg_);
    mutex_.unlock();
  }

  void stop() { publisher_.shutdown(); }

private:
  ros::NodeHandle node_;
  ros::Publisher publisher_;
  std::mutex mutex_;
};

template <class Msg>
using RealtimePublisherSharedPtr = std::shared_ptr<RealtimePublisher<Msg>>;

}  // namespace realtime_tools

#endif  // REALTIME_TOOLS__REALTIME_PUBLISHER_H_
