// colcon-rsia model of <boost/function.hpp>: boost::function<R(Args...)>.
// ROS callback types (ros::TimerCallback, the boost::function forms of
// subscribe and advertiseService) are specialisations of this template.
#ifndef RSIA_MODEL_BOOST_FUNCTION_HPP
#define RSIA_MODEL_BOOST_FUNCTION_HPP

#include <cstddef>
#include <type_traits>

namespace boost
{

template <class Signature>
class function;

template <class R, class... Args>
class function<R(Args...)>
{
public:
  typedef R result_type;

  function() noexcept;
  function(std::nullptr_t) noexcept;
  function(const function& other);
  function(function&& other) noexcept;
  // like boost: any callable, but not an integer (0 clears)
  template <class F, typename std::enable_if<!std::is_integral<F>::value, int>::type = 0>
  function(F f);
  ~function();

  function& operator=(const function& other);
  function& operator=(function&& other) noexcept;
  template <class F, typename std::enable_if<!std::is_integral<F>::value, int>::type = 0>
  function& operator=(F f);
  function& operator=(std::nullptr_t) noexcept;

  R operator()(Args... args) const;
  explicit operator bool() const noexcept;
  bool operator!() const noexcept;
  bool empty() const noexcept;
  void clear() noexcept;
  void swap(function& other) noexcept;
};

template <class Signature>
bool operator==(const function<Signature>& f, std::nullptr_t) noexcept;
template <class Signature>
bool operator!=(const function<Signature>& f, std::nullptr_t) noexcept;

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_FUNCTION_HPP
