// colcon-rsia model of <message_filters/message_event.hpp> (ROS 2): the
// message plus its receipt time, what filters pass along.
#ifndef RSIA_MODEL_MESSAGE_FILTERS_MESSAGE_EVENT_HPP
#define RSIA_MODEL_MESSAGE_FILTERS_MESSAGE_EVENT_HPP

#include <memory>
#include <type_traits>

#include <rclcpp/rclcpp.hpp>

namespace message_filters
{

template<typename M>
class MessageEvent
{
public:
  using ConstMessage = typename std::add_const<M>::type;
  using Message = typename std::remove_const<M>::type;
  using ConstMessagePtr = std::shared_ptr<ConstMessage>;

  MessageEvent();
  MessageEvent(const ConstMessagePtr & message);
  MessageEvent(const ConstMessagePtr & message, rclcpp::Time receipt_time);
  template<typename M2>
  MessageEvent(const MessageEvent<M2> & rhs);

  const ConstMessagePtr & getConstMessage() const;
  ConstMessagePtr getMessage() const;
  rclcpp::Time getReceiptTime() const;
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_MESSAGE_EVENT_HPP
