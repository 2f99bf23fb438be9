// colcon-rsia model of <ros/callback_queue.h>.
#ifndef RSIA_MODEL_ROS_CALLBACK_QUEUE_H
#define RSIA_MODEL_ROS_CALLBACK_QUEUE_H

#include <ros/callback_queue_interface.h>
#include <ros/time.h>

namespace ros
{

class CallbackQueue : public CallbackQueueInterface
{
public:
  CallbackQueue(bool enabled = true);
  virtual ~CallbackQueue();

  virtual void addCallback(const CallbackInterfacePtr& callback, uint64_t owner_id = 0);
  virtual void removeByID(uint64_t owner_id);

  enum CallOneResult
  {
    Called,
    TryAgain,
    Disabled,
    Empty,
  };
  CallOneResult callOne();
  CallOneResult callOne(ros::WallDuration timeout);
  void callAvailable();
  void callAvailable(ros::WallDuration timeout);
  bool empty();
  bool isEmpty();
  void clear();
  void enable();
  void disable();
  bool isEnabled();
};
typedef boost::shared_ptr<CallbackQueue> CallbackQueuePtr;

}  // namespace ros

#endif  // RSIA_MODEL_ROS_CALLBACK_QUEUE_H
