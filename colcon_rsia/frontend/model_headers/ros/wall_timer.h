// colcon-rsia model of <ros/wall_timer.h>.
#ifndef RSIA_MODEL_ROS_WALL_TIMER_H
#define RSIA_MODEL_ROS_WALL_TIMER_H

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

class WallTimer
{
public:
  WallTimer();
  WallTimer(const WallTimer& rhs);
  ~WallTimer();
  WallTimer& operator=(const WallTimer& other) = default;

  void start();
  void stop();
  bool hasPending();
  void setPeriod(const WallDuration& period, bool reset = true);
  bool hasStarted() const;
  bool isValid();
  operator void*();
  bool operator<(const WallTimer& rhs);
  bool operator==(const WallTimer& rhs);
  bool operator!=(const WallTimer& rhs);
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_WALL_TIMER_H
