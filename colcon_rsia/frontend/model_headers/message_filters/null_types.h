// colcon-rsia model of <message_filters/null_types.h>.
#ifndef RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES_H
#define RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES_H

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <message_filters/connection.h>
#include <ros/message_event.h>

namespace message_filters
{

struct NullType
{
};
typedef boost::shared_ptr<NullType const> NullTypeConstPtr;

template <class M>
struct NullFilter
{
  template <typename C>
  Connection registerCallback(const C&);
  template <typename P>
  Connection registerCallback(const boost::function<void(P)>&);
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_NULL_TYPES_H
