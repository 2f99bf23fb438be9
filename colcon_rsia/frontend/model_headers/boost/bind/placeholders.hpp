// colcon-rsia model of <boost/bind/placeholders.hpp>: boost::placeholders::_1.._9
// (global only through <boost/bind.hpp>, as with boost >= 1.73).
#ifndef RSIA_MODEL_BOOST_BIND_PLACEHOLDERS_HPP
#define RSIA_MODEL_BOOST_BIND_PLACEHOLDERS_HPP

namespace boost
{

template <int I>
struct arg
{
  constexpr arg()
  {
  }
};

namespace placeholders
{

static constexpr boost::arg<1> _1;
static constexpr boost::arg<2> _2;
static constexpr boost::arg<3> _3;
static constexpr boost::arg<4> _4;
static constexpr boost::arg<5> _5;
static constexpr boost::arg<6> _6;
static constexpr boost::arg<7> _7;
static constexpr boost::arg<8> _8;
static constexpr boost::arg<9> _9;

}  // namespace placeholders

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_BIND_PLACEHOLDERS_HPP
