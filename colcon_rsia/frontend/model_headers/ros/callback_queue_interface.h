// colcon-rsia model of <ros/callback_queue_interface.h>.
#ifndef RSIA_MODEL_ROS_CALLBACK_QUEUE_INTERFACE_H
#define RSIA_MODEL_ROS_CALLBACK_QUEUE_INTERFACE_H

#include <cstdint>

#include <boost/shared_ptr.hpp>

namespace ros
{

class CallbackInterface
{
public:
  enum CallResult
  {
    Success,
    TryAgain,
    Invalid,
  };
  virtual ~CallbackInterface();
  virtual CallResult call() = 0;
  virtual bool ready();
};
typedef boost::shared_ptr<CallbackInterface> CallbackInterfacePtr;

class CallbackQueueInterface
{
public:
  virtual ~CallbackQueueInterface();
  virtual void addCallback(const CallbackInterfacePtr& callback, uint64_t owner_id = 0) = 0;
  virtual void removeByID(uint64_t owner_id) = 0;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_CALLBACK_QUEUE_INTERFACE_H
