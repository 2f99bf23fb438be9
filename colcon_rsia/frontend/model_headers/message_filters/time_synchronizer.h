// colcon-rsia model of <message_filters/time_synchronizer.h>: a Synchronizer
// with the ExactTime policy, fed by 2..9 filters.
//
// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
// The ROS 2 class is in <message_filters/time_synchronizer.hpp>; both define
// RSIA_MODEL_MESSAGE_FILTERS_TIME_SYNCHRONIZER.
#ifdef RSIA_MODEL_RCLCPP
#include <message_filters/time_synchronizer.hpp>
#else  // ROS 1
#ifndef RSIA_MODEL_MESSAGE_FILTERS_TIME_SYNCHRONIZER
#define RSIA_MODEL_MESSAGE_FILTERS_TIME_SYNCHRONIZER

#include <cstdint>

#include <message_filters/sync_policies/exact_time.h>
#include <message_filters/synchronizer.h>

namespace message_filters
{

template <class M0, class M1, class M2 = NullType, class M3 = NullType, class M4 = NullType, class M5 = NullType, class M6 = NullType, class M7 = NullType, class M8 = NullType>
class TimeSynchronizer : public Synchronizer<sync_policies::ExactTime<M0, M1, M2, M3, M4, M5, M6, M7, M8>>
{
public:
  typedef sync_policies::ExactTime<M0, M1, M2, M3, M4, M5, M6, M7, M8> Policy;
  typedef Synchronizer<Policy> Base;
  typedef boost::shared_ptr<M0 const> M0ConstPtr;
  typedef boost::shared_ptr<M1 const> M1ConstPtr;

  using Base::add;
  using Base::connectInput;
  using Base::registerCallback;
  using Base::setName;
  using Base::getName;
  using Policy::registerDropCallback;

  template <class F0, class F1>
  TimeSynchronizer(F0& f0, F1& f1, uint32_t queue_size);
  template <class F0, class F1, class F2>
  TimeSynchronizer(F0& f0, F1& f1, F2& f2, uint32_t queue_size);
  template <class F0, class F1, class F2, class F3>
  TimeSynchronizer(F0& f0, F1& f1, F2& f2, F3& f3, uint32_t queue_size);
  template <class F0, class F1, class F2, class F3, class F4>
  TimeSynchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, uint32_t queue_size);
  template <class F0, class F1, class F2, class F3, class F4, class F5>
  TimeSynchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, uint32_t queue_size);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6>
  TimeSynchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6, uint32_t queue_size);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6, class F7>
  TimeSynchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6, F7& f7, uint32_t queue_size);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6, class F7, class F8>
  TimeSynchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6, F7& f7, F8& f8, uint32_t queue_size);
  TimeSynchronizer(uint32_t queue_size);

  void add0(const M0ConstPtr& msg);
  void add1(const M1ConstPtr& msg);
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_TIME_SYNCHRONIZER
#endif  // RSIA_MODEL_RCLCPP
