// colcon-rsia model of <rclcpp_lifecycle/lifecycle_publisher.hpp> (ROS 2)
#ifndef RSIA_MODEL_RCLCPP_LIFECYCLE_LIFECYCLE_PUBLISHER_HPP
#define RSIA_MODEL_RCLCPP_LIFECYCLE_LIFECYCLE_PUBLISHER_HPP

#include <rclcpp/rclcpp.hpp>

namespace rclcpp_lifecycle
{

template<class MessageT, class AllocatorT = std::allocator<void>>
class LifecyclePublisher : public rclcpp::Publisher<MessageT, AllocatorT>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(LifecyclePublisher)
  void publish(std::unique_ptr<MessageT> msg);
  void publish(const MessageT & msg);
  void publish(rclcpp::LoanedMessage<MessageT, AllocatorT> && loaned_msg);
  void on_activate();
  void on_deactivate();
  bool is_activated() const;
};

}  // namespace rclcpp_lifecycle

#endif  // RSIA_MODEL_RCLCPP_LIFECYCLE_LIFECYCLE_PUBLISHER_HPP
