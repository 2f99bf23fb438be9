// colcon-rsia model of <ros/steady_timer_options.h>.
#ifndef RSIA_MODEL_ROS_STEADY_TIMER_OPTIONS_H
#define RSIA_MODEL_ROS_STEADY_TIMER_OPTIONS_H

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

struct SteadyTimerOptions
{
  SteadyTimerOptions();
  SteadyTimerOptions(WallDuration _period, const SteadyTimerCallback& _callback, CallbackQueueInterface* _queue, bool oneshot = false,
      bool autostart = true);

  WallDuration period;
  SteadyTimerCallback callback;
  CallbackQueueInterface* callback_queue;
  VoidConstPtr tracked_object;
  bool oneshot;
  bool autostart;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_STEADY_TIMER_OPTIONS_H
