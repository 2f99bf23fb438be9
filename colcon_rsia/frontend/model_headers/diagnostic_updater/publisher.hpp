// colcon-rsia model of <diagnostic_updater/publisher.hpp> (ROS 2): topic
// diagnostics and DiagnosedPublisher (publishes through the rclcpp::Publisher
// it wraps).
#ifndef RSIA_MODEL_DIAGNOSTIC_UPDATER_PUBLISHER_HPP
#define RSIA_MODEL_DIAGNOSTIC_UPDATER_PUBLISHER_HPP

#include <memory>
#include <string>

#include <rclcpp/rclcpp.hpp>
#include <diagnostic_updater/diagnostic_updater.hpp>
#include <diagnostic_updater/update_functions.hpp>

namespace diagnostic_updater
{

class HeaderlessTopicDiagnostic : public CompositeDiagnosticTask
{
public:
  HeaderlessTopicDiagnostic(
    std::string name, diagnostic_updater::Updater & diag,
    const diagnostic_updater::FrequencyStatusParam & freq,
    const rclcpp::Clock::SharedPtr & clock = std::make_shared<rclcpp::Clock>());
  virtual ~HeaderlessTopicDiagnostic();
  virtual void tick();
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper & stat);
  void clear_window();
};

class TopicDiagnostic : public HeaderlessTopicDiagnostic
{
public:
  TopicDiagnostic(
    std::string name, diagnostic_updater::Updater & diag,
    const diagnostic_updater::FrequencyStatusParam & freq,
    const diagnostic_updater::TimeStampStatusParam & stamp,
    const rclcpp::Clock::SharedPtr & clock = std::make_shared<rclcpp::Clock>());
  virtual ~TopicDiagnostic();
  virtual void tick();
  virtual void tick(const rclcpp::Time & stamp);
};

template<typename MessageT, typename AllocatorT = std::allocator<void>>
class DiagnosedPublisher : public TopicDiagnostic
{
public:
  using PublisherT = rclcpp::Publisher<MessageT, AllocatorT>;
  using MessageUniquePtr = std::unique_ptr<MessageT>;

  DiagnosedPublisher(
    const typename PublisherT::SharedPtr & pub,
    diagnostic_updater::Updater & diag,
    const diagnostic_updater::FrequencyStatusParam & freq,
    const diagnostic_updater::TimeStampStatusParam & stamp,
    const rclcpp::Clock::SharedPtr & clock = std::make_shared<rclcpp::Clock>());
  virtual ~DiagnosedPublisher();

  virtual void publish(MessageUniquePtr message);
  virtual void publish(const MessageT & message);
  typename PublisherT::SharedPtr getPublisher() const;
  void setPublisher(typename PublisherT::SharedPtr pub);
};

}  // namespace diagnostic_updater

#endif  // RSIA_MODEL_DIAGNOSTIC_UPDATER_PUBLISHER_HPP
