// colcon-rsia model of <message_filters/sync_policies/approximate_time.hpp>
// (ROS 2).
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_APPROXIMATE_TIME
#define RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_APPROXIMATE_TIME

#include <cstdint>

#include <rclcpp/rclcpp.hpp>
#include <message_filters/connection.hpp>
#include <message_filters/null_types.hpp>
#include <message_filters/synchronizer.hpp>

namespace message_filters
{
namespace sync_policies
{

template<typename ... Ms>
struct ApproximateTime : public PolicyBase<Ms...>
{
  using Sync = Synchronizer<ApproximateTime>;
  using Super = PolicyBase<Ms...>;
  using Messages = typename Super::Messages;
  using Events = typename Super::Events;

  ApproximateTime(uint32_t queue_size);
  ApproximateTime(const ApproximateTime & e);
  ApproximateTime & operator=(const ApproximateTime & rhs);

  void initParent(Sync * parent);
  template<int i>
  void add(const typename std::tuple_element<i, Events>::type & evt);
  template<class C>
  Connection registerDropCallback(const C & callback);
  template<class C>
  Connection registerDropCallback(C & callback);
  template<class C, typename T>
  Connection registerDropCallback(const C & callback, T * t);
  template<class C, typename T>
  Connection registerDropCallback(C & callback, T * t);
  void setAgePenalty(double age_penalty);
  void setInterMessageLowerBound(int i, rclcpp::Duration lower_bound);
  void setInterMessageLowerBound(rclcpp::Duration lower_bound);
  void setMaxIntervalDuration(rclcpp::Duration max_interval_duration);
};

}  // namespace sync_policies
}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_APPROXIMATE_TIME
