// colcon-rsia model headers: which types a message field stand-in converts to.
#ifndef RSIA_MODEL_FIELD_TARGET_H
#define RSIA_MODEL_FIELD_TARGET_H

#include <type_traits>

namespace rsia_model
{

// A field of a generated message stand-in is a rsia_model::Any: it converts to
// double (all arithmetic uses) and to the class types for which this trait is
// true. Class types with a constructor from double (ros::Duration) stay out,
// so that `ros::Duration(msg.period)` is not ambiguous.
template <class V, class Enable = void>
struct field_target : std::false_type
{
};

// message stand-ins carry this tag
template <class V>
struct field_target<V, typename V::rsia_model_message_tag> : std::true_type
{
};

template <class... RsiaT>
using void_t = void;

// class-type iterators (std::vector<float>::const_reverse_iterator it =
// msg.ranges.rbegin()): nothing else converts to them
template <class V>
struct field_target<V, void_t<typename V::iterator_category>> : std::true_type
{
};

// scoped enumerations (`status.result = handler_result.second`, of a
// controller's return_type): nothing else converts to them, so no call
// overloaded on number types can tie with them
template <class V>
struct field_target<
    V, typename std::enable_if<std::is_enum<V>::value && !std::is_convertible<V, int>::value>::type>
  : std::true_type
{
};

}  // namespace rsia_model

#endif  // RSIA_MODEL_FIELD_TARGET_H
