// colcon-rsia model of <boost/lexical_cast.hpp>.
#ifndef RSIA_MODEL_BOOST_LEXICAL_CAST_HPP
#define RSIA_MODEL_BOOST_LEXICAL_CAST_HPP

#include <typeinfo>

namespace boost
{

class bad_lexical_cast : public std::bad_cast
{
};

template <class Target, class Source>
Target lexical_cast(const Source& arg);

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_LEXICAL_CAST_HPP
