// colcon-rsia model of <realtime_tools/realtime_publisher.hpp> (ROS 2; the
// Humble name <realtime_tools/realtime_publisher.h> includes it when rclcpp
// came first). The union of Humble, Jazzy and Rolling: the wrapper of an
// existing rclcpp::Publisher (H/J/R), the default constructor (H/J,
// deprecated), the constructor that creates the publisher itself from a
// node, a topic and a QoS (Rolling); the publish sites unlockAndPublish
// (after trylock and writing msg_; deprecated in Rolling) and try_publish
// (J/R; tryPublish is its deprecated H/J spelling).
#ifndef RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER
#define RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER

#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <rclcpp/rclcpp.hpp>

namespace realtime_tools
{

template<class MessageT>
class RealtimePublisher
{
public:
  using PublisherType = rclcpp::Publisher<MessageT>;
  using PublisherSharedPtr = typename rclcpp::Publisher<MessageT>::SharedPtr;
  RCLCPP_SMART_PTR_DEFINITIONS(RealtimePublisher<MessageT>)

  MessageT msg_;

  template<typename NodeT>
  explicit RealtimePublisher(
    NodeT && node, const std::string & topic_name, const rclcpp::QoS & qos,
    const rclcpp::PublisherOptions & options = rclcpp::PublisherOptions());
  explicit RealtimePublisher(PublisherSharedPtr publisher);
  RealtimePublisher();
  ~RealtimePublisher();
  RealtimePublisher(const RealtimePublisher &) = delete;
  RealtimePublisher & operator=(const RealtimePublisher &) = delete;

  void stop();
  bool trylock();
  bool can_publish() const;
  bool try_publish(const MessageT & msg);
  bool tryPublish(const MessageT & msg);
  void unlockAndPublish();
  void lock();
  void unlock();
  std::thread & get_thread();
  const MessageT & get_msg() const;
  std::mutex & get_mutex();
};

template<class MessageT>
using RealtimePublisherSharedPtr = std::shared_ptr<RealtimePublisher<MessageT>>;

}  // namespace realtime_tools

#endif  // RSIA_MODEL_REALTIME_TOOLS_REALTIME_PUBLISHER
