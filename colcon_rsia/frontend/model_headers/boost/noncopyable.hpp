// colcon-rsia model of <boost/noncopyable.hpp>.
#ifndef RSIA_MODEL_BOOST_NONCOPYABLE_HPP
#define RSIA_MODEL_BOOST_NONCOPYABLE_HPP

namespace boost
{

namespace noncopyable_
{

class noncopyable
{
protected:
  constexpr noncopyable() = default;
  ~noncopyable() = default;
  noncopyable(const noncopyable&) = delete;
  noncopyable& operator=(const noncopyable&) = delete;
};

}  // namespace noncopyable_

typedef noncopyable_::noncopyable noncopyable;

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_NONCOPYABLE_HPP
