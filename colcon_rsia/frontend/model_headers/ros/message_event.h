// colcon-rsia model of <ros/message_event.h>: ros::MessageEvent<M>, a
// subscriber callback parameter type (it appears in callback USRs).
#ifndef RSIA_MODEL_ROS_MESSAGE_EVENT_H
#define RSIA_MODEL_ROS_MESSAGE_EVENT_H

#include <string>
#include <type_traits>

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/datatypes.h>
#include <ros/time.h>

namespace ros
{

template <typename M>
struct DefaultMessageCreator
{
  boost::shared_ptr<M> operator()();
};

template <typename M>
class MessageEvent
{
public:
  typedef typename std::add_const<M>::type ConstMessage;
  typedef typename std::remove_const<M>::type Message;
  typedef boost::shared_ptr<Message> MessagePtr;
  typedef boost::shared_ptr<ConstMessage> ConstMessagePtr;
  typedef boost::function<MessagePtr()> CreateFunction;

  MessageEvent();
  MessageEvent(const MessageEvent<Message>& rhs);
  MessageEvent(const MessageEvent<ConstMessage>& rhs);
  MessageEvent(const ConstMessagePtr& message);
  MessageEvent(const ConstMessagePtr& message, const boost::shared_ptr<M_string>& connection_header,
               ros::Time receipt_time);
  MessageEvent(const ConstMessagePtr& message, ros::Time receipt_time);

  boost::shared_ptr<M> getMessage() const;
  const boost::shared_ptr<ConstMessage>& getConstMessage() const;
  M_string& getConnectionHeader() const;
  const boost::shared_ptr<M_string>& getConnectionHeaderPtr() const;
  const std::string& getPublisherName() const;
  ros::Time getReceiptTime() const;
  bool nonConstWillCopy() const;
  bool getMessageWillCopy() const;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_MESSAGE_EVENT_H
