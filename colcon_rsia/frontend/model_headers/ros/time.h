// colcon-rsia model of <ros/time.h>: TimeBase, Time, WallTime, SteadyTime.
#ifndef RSIA_MODEL_ROS_TIME_H
#define RSIA_MODEL_ROS_TIME_H

#include <rsia_model/std.h>
#include <cstdint>
#include <iosfwd>

#include <ros/duration.h>
#include <ros/exception.h>
#include <rsia_model/field_target.h>

namespace ros
{

class TimeNotInitializedException : public Exception
{
public:
  TimeNotInitializedException();
};

class NoHighPerformanceTimersException : public Exception
{
public:
  NoHighPerformanceTimersException();
};

template <class T, class D>
class TimeBase
{
public:
  uint32_t sec, nsec;

  TimeBase();
  TimeBase(uint32_t _sec, uint32_t _nsec);
  explicit TimeBase(double t);

  D operator-(const T& rhs) const;
  T operator+(const D& rhs) const;
  T operator-(const D& rhs) const;
  T& operator+=(const D& rhs);
  T& operator-=(const D& rhs);
  bool operator==(const T& rhs) const;
  bool operator!=(const T& rhs) const;
  bool operator>(const T& rhs) const;
  bool operator<(const T& rhs) const;
  bool operator>=(const T& rhs) const;
  bool operator<=(const T& rhs) const;

  double toSec() const;
  T& fromSec(double t);
  uint64_t toNSec() const;
  T& fromNSec(uint64_t t);
  bool isZero() const;
  bool is_zero() const;
};

class Time : public TimeBase<Time, Duration>
{
public:
  Time();
  Time(uint32_t _sec, uint32_t _nsec);
  explicit Time(double t);

  static Time now();
  static bool sleepUntil(const Time& end);
  static void init();
  static void shutdown();
  static void setNow(const Time& new_now);
  static bool useSystemTime();
  static bool isSimTime();
  static bool isSystemTime();
  static bool isValid();
  static bool waitForValid();
  static bool waitForValid(const ros::WallDuration& timeout);

  // Noetic's (newer than Debian's rostime)
  static const Time MIN;
  static const Time MAX;
  static const Time ZERO;
  static const Time UNINITIALIZED;
};

extern const Time TIME_MAX;
extern const Time TIME_MIN;

class WallTime : public TimeBase<WallTime, WallDuration>
{
public:
  WallTime();
  WallTime(uint32_t _sec, uint32_t _nsec);
  explicit WallTime(double t);

  static WallTime now();
  static bool sleepUntil(const WallTime& end);
  static bool isSystemTime();
};

class SteadyTime : public TimeBase<SteadyTime, WallDuration>
{
public:
  SteadyTime();
  SteadyTime(uint32_t _sec, uint32_t _nsec);
  explicit SteadyTime(double t);

  static SteadyTime now();
  static bool sleepUntil(const SteadyTime& end);
  static bool isSystemTime();
};

std::ostream& operator<<(std::ostream& os, const Time& rhs);
std::ostream& operator<<(std::ostream& os, const WallTime& rhs);
std::ostream& operator<<(std::ostream& os, const SteadyTime& rhs);

}  // namespace ros

namespace rsia_model
{

// `header.stamp` of a message stand-in reads as a ros::Time
template <>
struct field_target<ros::Time> : std::true_type
{
};

}  // namespace rsia_model

#endif  // RSIA_MODEL_ROS_TIME_H
