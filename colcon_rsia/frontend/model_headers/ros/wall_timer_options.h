// colcon-rsia model of <ros/wall_timer_options.h>.
#ifndef RSIA_MODEL_ROS_WALL_TIMER_OPTIONS_H
#define RSIA_MODEL_ROS_WALL_TIMER_OPTIONS_H

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

struct WallTimerOptions
{
  WallTimerOptions();
  WallTimerOptions(WallDuration _period, const WallTimerCallback& _callback, CallbackQueueInterface* _queue, bool oneshot = false,
      bool autostart = true);

  WallDuration period;
  WallTimerCallback callback;
  CallbackQueueInterface* callback_queue;
  VoidConstPtr tracked_object;
  bool oneshot;
  bool autostart;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_WALL_TIMER_OPTIONS_H
