// colcon-rsia model of <boost/bind.hpp>: boost::bind with the placeholders
// _1.._9 usable unqualified (the global using-directive of the real header).
#ifndef RSIA_MODEL_BOOST_BIND_HPP
#define RSIA_MODEL_BOOST_BIND_HPP

#include <boost/bind/bind.hpp>

#ifndef BOOST_BIND_NO_PLACEHOLDERS
using namespace boost::placeholders;
#endif

#endif  // RSIA_MODEL_BOOST_BIND_HPP
