// colcon-rsia model of <boost/shared_ptr.hpp>: boost::shared_ptr, weak_ptr and
// the pointer casts. Messages are passed as boost::shared_ptr<M const>, so this
// class template (one type parameter, namespace boost) appears in the USRs of
// user callbacks and must be this exact template.
#ifndef RSIA_MODEL_BOOST_SHARED_PTR_HPP
#define RSIA_MODEL_BOOST_SHARED_PTR_HPP

#include <cstddef>
#include <type_traits>

namespace boost
{

template <class T>
class weak_ptr;

template <class T>
class shared_ptr
{
public:
  typedef T element_type;

  shared_ptr() noexcept;
  shared_ptr(std::nullptr_t) noexcept;
  template <class Y>
  explicit shared_ptr(Y* p);
  template <class Y, class D>
  shared_ptr(Y* p, D d);
  template <class Y, class D, class A>
  shared_ptr(Y* p, D d, A a);
  shared_ptr(const shared_ptr& r) noexcept;
  shared_ptr(shared_ptr&& r) noexcept;
  template <class Y, typename std::enable_if<std::is_convertible<Y*, T*>::value, int>::type = 0>
  shared_ptr(const shared_ptr<Y>& r) noexcept;
  template <class Y, typename std::enable_if<std::is_convertible<Y*, T*>::value, int>::type = 0>
  shared_ptr(shared_ptr<Y>&& r) noexcept;
  template <class Y>
  shared_ptr(const shared_ptr<Y>& r, T* p) noexcept;
  template <class Y>
  explicit shared_ptr(const weak_ptr<Y>& r);

  shared_ptr& operator=(const shared_ptr& r) noexcept;
  shared_ptr& operator=(shared_ptr&& r) noexcept;
  template <class Y>
  shared_ptr& operator=(const shared_ptr<Y>& r) noexcept;

  void reset() noexcept;
  template <class Y>
  void reset(Y* p);
  template <class Y, class D>
  void reset(Y* p, D d);

  typename std::add_lvalue_reference<T>::type operator*() const noexcept;
  T* operator->() const noexcept;
  T* get() const noexcept;
  explicit operator bool() const noexcept;
  bool operator!() const noexcept;
  bool unique() const noexcept;
  long use_count() const noexcept;
  void swap(shared_ptr& other) noexcept;
};

template <class T, class U>
bool operator==(const shared_ptr<T>& a, const shared_ptr<U>& b) noexcept;
template <class T, class U>
bool operator!=(const shared_ptr<T>& a, const shared_ptr<U>& b) noexcept;
template <class T, class U>
bool operator<(const shared_ptr<T>& a, const shared_ptr<U>& b) noexcept;
template <class T>
bool operator==(const shared_ptr<T>& p, std::nullptr_t) noexcept;
template <class T>
bool operator==(std::nullptr_t, const shared_ptr<T>& p) noexcept;
template <class T>
bool operator!=(const shared_ptr<T>& p, std::nullptr_t) noexcept;
template <class T>
bool operator!=(std::nullptr_t, const shared_ptr<T>& p) noexcept;

template <class T, class U>
shared_ptr<T> static_pointer_cast(const shared_ptr<U>& r) noexcept;
template <class T, class U>
shared_ptr<T> const_pointer_cast(const shared_ptr<U>& r) noexcept;
template <class T, class U>
shared_ptr<T> dynamic_pointer_cast(const shared_ptr<U>& r) noexcept;
template <class T, class U>
shared_ptr<T> reinterpret_pointer_cast(const shared_ptr<U>& r) noexcept;

template <class T>
T* get_pointer(const shared_ptr<T>& p) noexcept;

template <class T>
class weak_ptr
{
public:
  typedef T element_type;

  weak_ptr() noexcept;
  weak_ptr(const weak_ptr& r) noexcept;
  template <class Y>
  weak_ptr(const weak_ptr<Y>& r) noexcept;
  template <class Y>
  weak_ptr(const shared_ptr<Y>& r) noexcept;
  weak_ptr& operator=(const weak_ptr& r) noexcept;
  template <class Y>
  weak_ptr& operator=(const shared_ptr<Y>& r) noexcept;

  shared_ptr<T> lock() const noexcept;
  bool expired() const noexcept;
  long use_count() const noexcept;
  void reset() noexcept;
};

template <class T>
class enable_shared_from_this
{
protected:
  enable_shared_from_this() noexcept;
  enable_shared_from_this(const enable_shared_from_this&) noexcept;
  enable_shared_from_this& operator=(const enable_shared_from_this&) noexcept;

public:
  shared_ptr<T> shared_from_this();
  shared_ptr<T const> shared_from_this() const;
  weak_ptr<T> weak_from_this() noexcept;
  weak_ptr<T const> weak_from_this() const noexcept;
};

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_SHARED_PTR_HPP
