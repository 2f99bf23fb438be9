// colcon-rsia model of <boost/bind/bind.hpp>: boost::bind.
// The analysis reads the first argument of a call to boost::bind (the bound
// function) and the arguments after it, so one variadic overload per shape
// (deduced and explicit result type) is enough.
#ifndef RSIA_MODEL_BOOST_BIND_BIND_HPP
#define RSIA_MODEL_BOOST_BIND_BIND_HPP

#include <boost/bind/placeholders.hpp>
#include <boost/ref.hpp>

namespace boost
{

namespace _bi
{

template <class... A>
class list
{
};

// the result of a function (pointer), member function (pointer) or functor
template <class F>
struct result_of_bound
{
  typedef void type;
};
template <class R, class... A>
struct result_of_bound<R (*)(A...)>
{
  typedef R type;
};
template <class R, class C, class... A>
struct result_of_bound<R (C::*)(A...)>
{
  typedef R type;
};
template <class R, class C, class... A>
struct result_of_bound<R (C::*)(A...) const>
{
  typedef R type;
};

template <class R, class F, class L>
class bind_t
{
public:
  typedef R result_type;

  template <class... A>
  result_type operator()(A&&... a);
  template <class... A>
  result_type operator()(A&&... a) const;
};

}  // namespace _bi

template <class F, class... A>
_bi::bind_t<typename _bi::result_of_bound<F>::type, F, _bi::list<A...>> bind(F f, A... a);

template <class R, class F, class... A>
_bi::bind_t<R, F, _bi::list<A...>> bind(F f, A... a);

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_BIND_BIND_HPP
