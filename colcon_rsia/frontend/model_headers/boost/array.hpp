// colcon-rsia model of <boost/array.hpp> (fixed-size message arrays in ROS 1).
#ifndef RSIA_MODEL_BOOST_ARRAY_HPP
#define RSIA_MODEL_BOOST_ARRAY_HPP

#include <cstddef>

#include <rsia_model/field_target.h>

namespace boost
{

template <class T, std::size_t N>
class array
{
public:
  T elems[N ? N : 1];

  typedef T value_type;
  typedef T* iterator;
  typedef const T* const_iterator;
  typedef T& reference;
  typedef const T& const_reference;
  typedef std::size_t size_type;

  iterator begin();
  const_iterator begin() const;
  iterator end();
  const_iterator end() const;
  reference operator[](size_type i);
  const_reference operator[](size_type i) const;
  reference at(size_type i);
  const_reference at(size_type i) const;
  reference front();
  reference back();
  static constexpr size_type size();
  static constexpr bool empty();
  T* data();
  const T* data() const;
  T* c_array();
  void fill(const T& value);
  void assign(const T& value);
};

}  // namespace boost

namespace rsia_model
{

template <class T, std::size_t N>
struct field_target<boost::array<T, N>> : std::true_type
{
};

}  // namespace rsia_model

#endif  // RSIA_MODEL_BOOST_ARRAY_HPP
