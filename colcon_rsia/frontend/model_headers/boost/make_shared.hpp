// colcon-rsia model of <boost/make_shared.hpp>.
#ifndef RSIA_MODEL_BOOST_MAKE_SHARED_HPP
#define RSIA_MODEL_BOOST_MAKE_SHARED_HPP

#include <boost/shared_ptr.hpp>

namespace boost
{

template <class T, class... Args>
shared_ptr<T> make_shared(Args&&... args);

template <class T, class A, class... Args>
shared_ptr<T> allocate_shared(const A& allocator, Args&&... args);

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_MAKE_SHARED_HPP
