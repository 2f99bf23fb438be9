// colcon-rsia model of <ros/timer.h>.
#ifndef RSIA_MODEL_ROS_TIMER_H
#define RSIA_MODEL_ROS_TIMER_H

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

class Timer
{
public:
  Timer();
  Timer(const Timer& rhs);
  ~Timer();
  Timer& operator=(const Timer& other) = default;

  void start();
  void stop();
  bool hasPending();
  void setPeriod(const Duration& period, bool reset = true);
  bool hasStarted() const;
  bool isValid();
  operator void*();
  bool operator<(const Timer& rhs);
  bool operator==(const Timer& rhs);
  bool operator!=(const Timer& rhs);
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_TIMER_H
