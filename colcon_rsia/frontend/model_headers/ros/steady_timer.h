// colcon-rsia model of <ros/steady_timer.h>.
#ifndef RSIA_MODEL_ROS_STEADY_TIMER_H
#define RSIA_MODEL_ROS_STEADY_TIMER_H

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

class SteadyTimer
{
public:
  SteadyTimer();
  SteadyTimer(const SteadyTimer& rhs);
  ~SteadyTimer();
  SteadyTimer& operator=(const SteadyTimer& other) = default;

  void start();
  void stop();
  bool hasPending();
  void setPeriod(const WallDuration& period, bool reset = true);
  bool hasStarted() const;
  bool isValid();
  operator void*();
  bool operator<(const SteadyTimer& rhs);
  bool operator==(const SteadyTimer& rhs);
  bool operator!=(const SteadyTimer& rhs);
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_STEADY_TIMER_H
