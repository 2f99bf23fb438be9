// colcon-rsia model of <ros/message_traits.h>: the traits a generated
// message specialises, and code that makes its own types messages
// (`template<> struct MD5Sum<MyType>`, `HasHeader<MyType> : TrueType`).
// The model cannot know a message's checksum or definition: its values
// are placeholders, and the model's ROS_STATIC_ASSERT checks nothing.
#ifndef RSIA_MODEL_ROS_MESSAGE_TRAITS_H
#define RSIA_MODEL_ROS_MESSAGE_TRAITS_H

#include <cstdint>
#include <string>

#include <ros/time.h>

namespace ros
{
namespace message_traits
{

struct TrueType
{
  static const bool value = true;
  typedef TrueType type;
};

struct FalseType
{
  static const bool value = false;
  typedef FalseType type;
};

template <typename M> struct IsSimple : public FalseType {};
template <typename M> struct IsFixedSize : public FalseType {};
template <typename M> struct HasHeader : public FalseType {};
template <typename M> struct IsMessage : public FalseType {};

template <typename M>
struct MD5Sum
{
  static const char * value() { return ""; }
  static const char * value(const M &) { return value(); }
  static const uint64_t static_value1 = 0;
  static const uint64_t static_value2 = 0;
};

template <typename M>
struct DataType
{
  static const char * value() { return ""; }
  static const char * value(const M &) { return value(); }
};

template <typename M>
struct Definition
{
  static const char * value() { return ""; }
  static const char * value(const M &) { return value(); }
};

template <typename M, typename Enable = void>
struct Header
{
  static void * pointer(M &) { return nullptr; }
  static void const * pointer(const M &) { return nullptr; }
};

template <typename M, typename Enable = void>
struct FrameId
{
  static std::string * pointer(M &) { return nullptr; }
  static std::string const * pointer(const M &) { return nullptr; }
  static std::string value(const M &) { return std::string(); }
};

template <typename M, typename Enable = void>
struct TimeStamp
{
  static ros::Time * pointer(M &) { return nullptr; }
  static ros::Time const * pointer(const M &) { return nullptr; }
  static ros::Time value(const M &) { return ros::Time(); }
};

template <typename M> inline const char * md5sum() { return MD5Sum<M>::value(); }
template <typename M> inline const char * datatype() { return DataType<M>::value(); }
template <typename M> inline const char * definition() { return Definition<M>::value(); }
template <typename M> inline const char * md5sum(const M & m) { return MD5Sum<M>::value(m); }
template <typename M> inline const char * datatype(const M & m) { return DataType<M>::value(m); }
template <typename M> inline const char * definition(const M & m) { return Definition<M>::value(m); }
template <typename M> inline bool isSimple() { return IsSimple<M>::value; }
template <typename M> inline bool isFixedSize() { return IsFixedSize<M>::value; }
template <typename M> inline bool hasHeader() { return HasHeader<M>::value; }

}  // namespace message_traits
}  // namespace ros

#endif  // RSIA_MODEL_ROS_MESSAGE_TRAITS_H
