// colcon-rsia model of <boost/ref.hpp>: boost::ref, boost::cref.
#ifndef RSIA_MODEL_BOOST_REF_HPP
#define RSIA_MODEL_BOOST_REF_HPP

namespace boost
{

template <class T>
class reference_wrapper
{
public:
  typedef T type;

  explicit reference_wrapper(T& t);
  operator T&() const;
  T& get() const;
  T* get_pointer() const;
};

template <class T>
reference_wrapper<T> const ref(T& t);
template <class T>
reference_wrapper<T const> const cref(T const& t);

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_REF_HPP
