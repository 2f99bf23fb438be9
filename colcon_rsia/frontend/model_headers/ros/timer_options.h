// colcon-rsia model of <ros/timer_options.h>.
#ifndef RSIA_MODEL_ROS_TIMER_OPTIONS_H
#define RSIA_MODEL_ROS_TIMER_OPTIONS_H

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

struct TimerOptions
{
  TimerOptions();
  TimerOptions(Duration _period, const TimerCallback& _callback, CallbackQueueInterface* _queue, bool oneshot = false,
      bool autostart = true);

  Duration period;
  TimerCallback callback;
  CallbackQueueInterface* callback_queue;
  VoidConstPtr tracked_object;
  bool oneshot;
  bool autostart;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_TIMER_OPTIONS_H
