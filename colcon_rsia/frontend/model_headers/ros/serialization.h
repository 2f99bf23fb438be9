// colcon-rsia model of <ros/serialization.h>: the serializer a generated
// message specialises, and code that makes its own types messages
// (`template<> struct Serializer<MyType>` with write/read/serializedLength).
#ifndef RSIA_MODEL_ROS_SERIALIZATION_H
#define RSIA_MODEL_ROS_SERIALIZATION_H

#include <cstdint>

#include <ros/message_traits.h>

namespace ros
{
namespace serialization
{

template <typename T>
struct Serializer
{
  template <typename Stream> inline static void write(Stream &, const T &) {}
  template <typename Stream> inline static void read(Stream &, T &) {}
  inline static uint32_t serializedLength(const T &) { return 0; }
};

template <typename T, typename Stream>
inline void serialize(Stream & stream, const T & t)
{
  Serializer<T>::write(stream, t);
}

template <typename T, typename Stream>
inline void deserialize(Stream & stream, T & t)
{
  Serializer<T>::read(stream, t);
}

template <typename T>
inline uint32_t serializationLength(const T & t)
{
  return Serializer<T>::serializedLength(t);
}

// the streams a serializer is handed (next() one value, advance() raw bytes)
struct Stream
{
  uint8_t * getData();
  uint8_t * advance(uint32_t len);
  uint32_t getLength() const;
};

struct IStream : public Stream
{
  IStream(uint8_t * data, uint32_t count);
  template <typename T> void next(T & t) { deserialize(*this, t); }
  template <typename T> IStream & operator>>(T & t) { next(t); return *this; }
};

struct OStream : public Stream
{
  OStream(uint8_t * data, uint32_t count);
  template <typename T> void next(const T & t) { serialize(*this, t); }
  template <typename T> OStream & operator<<(const T & t) { next(t); return *this; }
};

struct LStream
{
  template <typename T> void next(const T & t) { serializationLength(t); }
  uint32_t advance(uint32_t len);
  uint32_t getLength();
};

}  // namespace serialization
}  // namespace ros

#endif  // RSIA_MODEL_ROS_SERIALIZATION_H
