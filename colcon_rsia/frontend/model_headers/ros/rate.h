// colcon-rsia model of <ros/rate.h>: Rate and WallRate, whose sleep() is the
// adaptive sleep that paces a rate loop. Rate(double) is implicit.
#ifndef RSIA_MODEL_ROS_RATE_H
#define RSIA_MODEL_ROS_RATE_H

#include <ros/time.h>

namespace ros
{

class Duration;

class Rate
{
public:
  Rate(double frequency);
  explicit Rate(const Duration&);

  bool sleep();
  void reset();
  Duration cycleTime() const;
  Duration expectedCycleTime() const;
};

class WallRate
{
public:
  WallRate(double frequency);
  explicit WallRate(const Duration&);

  bool sleep();
  void reset();
  WallDuration cycleTime() const;
  WallDuration expectedCycleTime() const;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_RATE_H
