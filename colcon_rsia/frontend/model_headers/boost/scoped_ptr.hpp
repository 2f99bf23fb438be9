// colcon-rsia model of <boost/scoped_ptr.hpp>.
#ifndef RSIA_MODEL_BOOST_SCOPED_PTR_HPP
#define RSIA_MODEL_BOOST_SCOPED_PTR_HPP

#include <type_traits>

namespace boost
{

template <class T>
class scoped_ptr
{
public:
  typedef T element_type;

  explicit scoped_ptr(T* p = nullptr);
  ~scoped_ptr();
  scoped_ptr(const scoped_ptr&) = delete;
  scoped_ptr& operator=(const scoped_ptr&) = delete;

  void reset(T* p = nullptr);
  typename std::add_lvalue_reference<T>::type operator*() const;
  T* operator->() const;
  T* get() const;
  explicit operator bool() const;
  bool operator!() const;
  void swap(scoped_ptr& other);
};

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_SCOPED_PTR_HPP
