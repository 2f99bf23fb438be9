// colcon-rsia model of <tf/message_filter.h>: a message filter (no topic of its
// own) whose registerCallback is message_filters::SimpleFilter's.
#ifndef RSIA_MODEL_TF_MESSAGE_FILTER_H
#define RSIA_MODEL_TF_MESSAGE_FILTER_H

#include <cstdint>
#include <string>
#include <vector>

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <message_filters/connection.h>
#include <message_filters/simple_filter.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <tf/tf.h>

namespace tf
{

namespace filter_failure_reasons
{

enum FilterFailureReason
{
  Unknown,
  OutTheBack,
  EmptyFrameID,
};

}  // namespace filter_failure_reasons
typedef filter_failure_reasons::FilterFailureReason FilterFailureReason;

class MessageFilterBase
{
public:
  typedef std::vector<std::string> V_string;

  virtual ~MessageFilterBase();
  virtual void clear() = 0;
  virtual void setTargetFrame(const std::string& target_frame) = 0;
  virtual void setTargetFrames(const V_string& target_frames) = 0;
  virtual void setTolerance(const ros::Duration& tolerance) = 0;
};

template <class M>
class MessageFilter : public MessageFilterBase, public message_filters::SimpleFilter<M>
{
public:
  typedef boost::shared_ptr<M const> MConstPtr;
  typedef ros::MessageEvent<M const> MEvent;
  typedef boost::function<void(const MConstPtr&, FilterFailureReason)> FailureCallback;

  MessageFilter(Transformer& tf, const std::string& target_frame, uint32_t queue_size,
                ros::NodeHandle nh = ros::NodeHandle(), ros::Duration max_rate = ros::Duration(0.01));
  template <class F>
  MessageFilter(F& f, Transformer& tf, const std::string& target_frame, uint32_t queue_size,
                ros::NodeHandle nh = ros::NodeHandle(), ros::Duration max_rate = ros::Duration(0.01));
  ~MessageFilter();

  template <class F>
  void connectInput(F& f);
  void setTargetFrame(const std::string& target_frame);
  void setTargetFrames(const V_string& target_frames);
  std::string getTargetFramesString();
  void setTolerance(const ros::Duration& tolerance);
  void clear();
  void add(const MEvent& evt);
  void add(const MConstPtr& message);
  message_filters::Connection registerFailureCallback(const FailureCallback& callback);
  virtual void setQueueSize(uint32_t new_queue_size);
  virtual uint32_t getQueueSize();
};

}  // namespace tf

#endif  // RSIA_MODEL_TF_MESSAGE_FILTER_H
