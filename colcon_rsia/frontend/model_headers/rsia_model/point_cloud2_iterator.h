// colcon-rsia model: the classes of sensor_msgs' point_cloud2_iterator
// header, over the cloud message RSIA_MODEL_POINT_CLOUD2_CLOUD (ROS 1 or
// ROS 2), included once by sensor_msgs/point_cloud2_iterator.h(pp).
#ifndef RSIA_MODEL_POINT_CLOUD2_ITERATOR_H
#define RSIA_MODEL_POINT_CLOUD2_ITERATOR_H

// the header's helpers, in an unnamed namespace at global scope (code
// calls them unqualified): a field type's size, a field added to a cloud
namespace
{
inline int sizeOfPointField(int datatype)
{
  return datatype;
}
inline int addPointField(
  RSIA_MODEL_POINT_CLOUD2_CLOUD & cloud_msg, const std::string & name,
  int count, int datatype, int offset)
{
  return offset;
}
}  // namespace

namespace sensor_msgs
{

class PointCloud2Modifier
{
public:
  explicit PointCloud2Modifier(RSIA_MODEL_POINT_CLOUD2_CLOUD & cloud_msg);
  size_t size() const;
  void reserve(size_t size);
  void resize(size_t size);
  void clear();
  void setPointCloud2Fields(int n_fields, ...);
  void setPointCloud2FieldsByString(int n_fields, ...);
};

namespace impl
{
// what both iterators do: dereference to the field's value, step, compare
template<typename T, typename TT, typename V>
class PointCloud2IteratorBase
{
public:
  TT & operator[](size_t i) const;
  TT & operator*() const;
  V & operator++();
  V operator+(int i);
  V & operator+=(int i);
  bool operator!=(const V & iter) const;
  V end() const;
};
}  // namespace impl

template<typename T>
class PointCloud2Iterator
  : public impl::PointCloud2IteratorBase<T, T, PointCloud2Iterator<T>>
{
public:
  PointCloud2Iterator();
  PointCloud2Iterator(
    RSIA_MODEL_POINT_CLOUD2_CLOUD & cloud_msg, const std::string & field_name);
};

template<typename T>
class PointCloud2ConstIterator
  : public impl::PointCloud2IteratorBase<T, const T, PointCloud2ConstIterator<T>>
{
public:
  PointCloud2ConstIterator();
  PointCloud2ConstIterator(
    const RSIA_MODEL_POINT_CLOUD2_CLOUD & cloud_msg, const std::string & field_name);
};

}  // namespace sensor_msgs

#endif  // RSIA_MODEL_POINT_CLOUD2_ITERATOR_H
