// colcon-rsia model of <boost/foreach.hpp>: BOOST_FOREACH and
// BOOST_REVERSE_FOREACH.
//
// The real expansion is a chain of three if/else statements, an outer `for`
// whose condition and increment test and advance the iterator, an if/else and
// an inner `for` that declares the loop variable; the collection expression
// is written 14 times in the if chain, 4 times in the outer `for` and twice in
// the inner one. The analysis records every call in that expression with the
// loops around it, so this model keeps the same skeleton and the same number
// of copies in each place (the helpers below are never run).
#ifndef RSIA_MODEL_BOOST_FOREACH_HPP
#define RSIA_MODEL_BOOST_FOREACH_HPP

#include <iterator>

namespace boost
{

namespace foreach_detail_
{

struct rsia_any
{
  explicit operator bool() const;
};

template <class... C>
rsia_any rsia_hold(const C&...);
template <class... C>
bool rsia_done(const C&...);
template <class... C>
void rsia_next(const C&...);
bool rsia_set_false(bool& flag);
template <class C, class... More>
auto rsia_element(C&& col, const More&...) -> decltype(*std::begin(col));
template <class C, class... More>
auto rsia_reverse_element(C&& col, const More&...) -> decltype(*std::rbegin(col));

}  // namespace foreach_detail_

}  // namespace boost

#define RSIA_FOREACH_(VAR, COL, ELEMENT)                                                                  \
  if (::boost::foreach_detail_::rsia_any rsia_foreach_col_ =                                             \
          ::boost::foreach_detail_::rsia_hold(COL, COL, COL, COL, COL))                                  \
  {                                                                                                      \
  }                                                                                                      \
  else if (::boost::foreach_detail_::rsia_any rsia_foreach_cur_ =                                        \
               ::boost::foreach_detail_::rsia_hold(COL, COL, COL, COL, COL))                             \
  {                                                                                                      \
  }                                                                                                      \
  else if (::boost::foreach_detail_::rsia_any rsia_foreach_end_ =                                        \
               ::boost::foreach_detail_::rsia_hold(COL, COL, COL, COL))                                  \
  {                                                                                                      \
  }                                                                                                      \
  else                                                                                                   \
    for (bool rsia_foreach_continue_ = true;                                                             \
         rsia_foreach_continue_ && !::boost::foreach_detail_::rsia_done(COL, COL);                       \
         rsia_foreach_continue_ ? ::boost::foreach_detail_::rsia_next(COL, COL) : (void)0)               \
      if (::boost::foreach_detail_::rsia_set_false(rsia_foreach_continue_))                              \
      {                                                                                                  \
      }                                                                                                  \
      else                                                                                               \
        for (VAR = ::boost::foreach_detail_::ELEMENT(COL, COL); !rsia_foreach_continue_;                 \
             rsia_foreach_continue_ = true)

#define BOOST_FOREACH(VAR, COL) RSIA_FOREACH_(VAR, COL, rsia_element)
#define BOOST_REVERSE_FOREACH(VAR, COL) RSIA_FOREACH_(VAR, COL, rsia_reverse_element)

#endif  // RSIA_MODEL_BOOST_FOREACH_HPP
