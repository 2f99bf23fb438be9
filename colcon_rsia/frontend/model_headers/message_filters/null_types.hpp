// colcon-rsia model of <message_filters/null_types.hpp> (ROS 2).
#ifndef RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES
#define RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES

#include <functional>
#include <memory>

#include <message_filters/connection.hpp>

namespace message_filters
{

struct NullType
{
};
using NullTypeConstPtr = std::shared_ptr<NullType const>;

template<class M>
struct NullFilter
{
  template<typename C>
  Connection registerCallback(const C &);
  template<typename P>
  Connection registerCallback(const std::function<void(P)> &);
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES
