// colcon-rsia model of <ros/duration.h>: DurationBase, Duration, WallDuration.
// Duration(double) is explicit and Duration(const Rate&) exists: a bare number
// given to createTimer therefore selects its Rate form (Hz).
#ifndef RSIA_MODEL_ROS_DURATION_H
#define RSIA_MODEL_ROS_DURATION_H

#include <cstdint>
#include <iosfwd>

#include <ros/exception.h>
#include <ros/macros.h>

namespace ros
{

void normalizeSecNSec(uint64_t& sec, uint64_t& nsec);
void normalizeSecNSec(uint32_t& sec, uint32_t& nsec);
void normalizeSecNSecSigned(int64_t& sec, int64_t& nsec);
void normalizeSecNSecSigned(int32_t& sec, int32_t& nsec);

template <class T>
class DurationBase
{
public:
  int32_t sec, nsec;

  DurationBase();
  DurationBase(int32_t _sec, int32_t _nsec);
  explicit DurationBase(double t);

  T operator+(const T& rhs) const;
  T operator-(const T& rhs) const;
  T operator-() const;
  T operator*(double scale) const;
  T& operator+=(const T& rhs);
  T& operator-=(const T& rhs);
  T& operator*=(double scale);
  bool operator==(const T& rhs) const;
  bool operator!=(const T& rhs) const;
  bool operator>(const T& rhs) const;
  bool operator<(const T& rhs) const;
  bool operator>=(const T& rhs) const;
  bool operator<=(const T& rhs) const;
  double toSec() const;
  int64_t toNSec() const;
  T& fromSec(double t);
  T& fromNSec(int64_t t);
  bool isZero() const;
};

class Rate;

class Duration : public DurationBase<Duration>
{
public:
  Duration();
  Duration(int32_t _sec, int32_t _nsec);
  explicit Duration(double t);
  explicit Duration(const Rate&);

  // sleeps for this duration (not adaptive: a loop paced by it is not a rate loop)
  bool sleep() const;

  // Noetic's (newer than Debian's rostime)
  static const Duration MIN;
  static const Duration MAX;
  static const Duration ZERO;
  static const Duration UNINITIALIZED;
};

extern const Duration DURATION_MAX;
extern const Duration DURATION_MIN;

class WallDuration : public DurationBase<WallDuration>
{
public:
  WallDuration();
  WallDuration(int32_t _sec, int32_t _nsec);
  explicit WallDuration(double t);
  explicit WallDuration(const Rate&);

  bool sleep() const;
};

std::ostream& operator<<(std::ostream& os, const Duration& rhs);
std::ostream& operator<<(std::ostream& os, const WallDuration& rhs);

}  // namespace ros

#endif  // RSIA_MODEL_ROS_DURATION_H
