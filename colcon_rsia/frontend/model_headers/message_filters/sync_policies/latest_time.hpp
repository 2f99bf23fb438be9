// colcon-rsia model of <message_filters/sync_policies/latest_time.hpp>
// (ROS 2, Humble+ as latest_time.h).
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_LATEST_TIME
#define RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_LATEST_TIME

#include <rclcpp/rclcpp.hpp>
#include <message_filters/connection.hpp>
#include <message_filters/null_types.hpp>
#include <message_filters/synchronizer.hpp>

namespace message_filters
{
namespace sync_policies
{

template<typename ... Ms>
struct LatestTime : public PolicyBase<Ms...>
{
  using Sync = Synchronizer<LatestTime>;
  using Super = PolicyBase<Ms...>;
  using Messages = typename Super::Messages;
  using Events = typename Super::Events;

  LatestTime();
  explicit LatestTime(rclcpp::Clock::SharedPtr clock);
  LatestTime(const LatestTime & e);
  LatestTime & operator=(const LatestTime & rhs);

  void initParent(Sync * parent);
  template<int i>
  void add(const typename std::tuple_element<i, Events>::type & evt);
  void setRateConfigPerMsg(...);
};

}  // namespace sync_policies
}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_LATEST_TIME
