// colcon-rsia model of <message_filters/sync_policies/exact_time.h>.
//
// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
// The ROS 2 class is in <message_filters/sync_policies/exact_time.hpp>; both define
// RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_EXACT_TIME.
#ifdef RSIA_MODEL_RCLCPP
#include <message_filters/sync_policies/exact_time.hpp>
#else  // ROS 1
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_EXACT_TIME
#define RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_EXACT_TIME

#include <cstdint>

#include <message_filters/connection.h>
#include <message_filters/null_types.h>
#include <message_filters/synchronizer.h>
#include <ros/ros.h>

namespace message_filters
{

namespace sync_policies
{

template <typename M0, typename M1, typename M2 = NullType, typename M3 = NullType, typename M4 = NullType, typename M5 = NullType, typename M6 = NullType, typename M7 = NullType, typename M8 = NullType>
struct ExactTime : public PolicyBase<M0, M1, M2, M3, M4, M5, M6, M7, M8>
{
  typedef Synchronizer<ExactTime> Sync;
  typedef PolicyBase<M0, M1, M2, M3, M4, M5, M6, M7, M8> Super;

  ExactTime(uint32_t queue_size);
  ExactTime(const ExactTime& e);
  ExactTime& operator=(const ExactTime& rhs);

  void initParent(Sync* parent);
  template <int i>
  void add(const typename Super::M0Event& evt);
  template <class C>
  Connection registerDropCallback(const C& callback);
  template <class C>
  Connection registerDropCallback(C& callback);
  template <class C, typename T>
  Connection registerDropCallback(const C& callback, T* t);
  template <class C, typename T>
  Connection registerDropCallback(C& callback, T* t);
  void setReset(const bool reset);
};

}  // namespace sync_policies

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_EXACT_TIME
#endif  // RSIA_MODEL_RCLCPP
