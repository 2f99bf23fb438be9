// colcon-rsia model of <message_filters/sync_policies/exact_time.hpp> (ROS 2).
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_EXACT_TIME
#define RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_EXACT_TIME

#include <cstdint>

#include <message_filters/connection.hpp>
#include <message_filters/null_types.hpp>
#include <message_filters/synchronizer.hpp>

namespace message_filters
{
namespace sync_policies
{

template<typename ... Ms>
struct ExactTime : public PolicyBase<Ms...>
{
  using Sync = Synchronizer<ExactTime>;
  using Super = PolicyBase<Ms...>;
  using Messages = typename Super::Messages;
  using Events = typename Super::Events;

  ExactTime(uint32_t queue_size);
  ExactTime(const ExactTime & e);
  ExactTime & operator=(const ExactTime & rhs);

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
};

}  // namespace sync_policies
}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SYNC_POLICIES_EXACT_TIME
