// colcon-rsia model of <message_filters/time_synchronizer.hpp> (ROS 2): a
// Synchronizer with the ExactTime policy, fed by 2..9 filters.
#ifndef RSIA_MODEL_MESSAGE_FILTERS_TIME_SYNCHRONIZER
#define RSIA_MODEL_MESSAGE_FILTERS_TIME_SYNCHRONIZER

#include <cstdint>
#include <memory>

#include <message_filters/sync_policies/exact_time.hpp>
#include <message_filters/synchronizer.hpp>

namespace message_filters
{

template<class ... Ms>
class TimeSynchronizer : public Synchronizer<sync_policies::ExactTime<Ms...>>
{
public:
  using Policy = sync_policies::ExactTime<Ms...>;
  using Base = Synchronizer<Policy>;

  using Base::add;
  using Base::connectInput;
  using Base::registerCallback;
  using Base::setName;
  using Base::getName;
  using Policy::registerDropCallback;

  template<class F0, class F1>
  TimeSynchronizer(F0 & f0, F1 & f1, uint32_t queue_size);
  template<class F0, class F1, class F2>
  TimeSynchronizer(F0 & f0, F1 & f1, F2 & f2, uint32_t queue_size);
  template<class F0, class F1, class F2, class F3>
  TimeSynchronizer(F0 & f0, F1 & f1, F2 & f2, F3 & f3, uint32_t queue_size);
  template<class F0, class F1, class F2, class F3, class F4>
  TimeSynchronizer(F0 & f0, F1 & f1, F2 & f2, F3 & f3, F4 & f4, uint32_t queue_size);
  template<class F0, class F1, class F2, class F3, class F4, class F5>
  TimeSynchronizer(
    F0 & f0, F1 & f1, F2 & f2, F3 & f3, F4 & f4, F5 & f5, uint32_t queue_size);
  template<class F0, class F1, class F2, class F3, class F4, class F5, class F6>
  TimeSynchronizer(
    F0 & f0, F1 & f1, F2 & f2, F3 & f3, F4 & f4, F5 & f5, F6 & f6,
    uint32_t queue_size);
  template<class F0, class F1, class F2, class F3, class F4, class F5, class F6,
    class F7>
  TimeSynchronizer(
    F0 & f0, F1 & f1, F2 & f2, F3 & f3, F4 & f4, F5 & f5, F6 & f6, F7 & f7,
    uint32_t queue_size);
  template<class F0, class F1, class F2, class F3, class F4, class F5, class F6,
    class F7, class F8>
  TimeSynchronizer(
    F0 & f0, F1 & f1, F2 & f2, F3 & f3, F4 & f4, F5 & f5, F6 & f6, F7 & f7,
    F8 & f8, uint32_t queue_size);
  TimeSynchronizer(uint32_t queue_size);
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_TIME_SYNCHRONIZER
