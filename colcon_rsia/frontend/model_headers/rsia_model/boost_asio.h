// colcon-rsia model of the parts of Boost.Asio that pace ROS nodes: the
// io_context and its timers (waitable timers on std::chrono clocks, the
// deadline_timer on posix_time), with the handler-taking async_wait. Also
// the posix_time durations and boost::system::error_code they use. Included
// by the <boost/asio*.hpp>, <boost/system/...> and <boost/date_time/...>
// model headers.
#ifndef RSIA_MODEL_BOOST_ASIO_H
#define RSIA_MODEL_BOOST_ASIO_H

#include <chrono>
#include <cstddef>
#include <string>

namespace boost
{
namespace system
{
class error_code
{
public:
  error_code() noexcept;
  int value() const noexcept;
  std::string message() const;
  explicit operator bool() const noexcept;
  bool operator!() const noexcept;
};
}  // namespace system

namespace posix_time
{
class time_duration
{
public:
  time_duration();
  long total_milliseconds() const;
  long total_seconds() const;
};
class hours : public time_duration
{
public:
  explicit hours(long count);
};
class minutes : public time_duration
{
public:
  explicit minutes(long count);
};
class seconds : public time_duration
{
public:
  explicit seconds(long count);
};
class milliseconds : public time_duration
{
public:
  explicit milliseconds(long count);
};
class microseconds : public time_duration
{
public:
  explicit microseconds(long count);
};
class ptime
{
public:
  ptime();
};
ptime operator+(const ptime &, const time_duration &);
ptime operator-(const ptime &, const time_duration &);
}  // namespace posix_time

namespace asio
{
class io_context
{
public:
  io_context();
  explicit io_context(int concurrency_hint);
  std::size_t run();
  std::size_t run_one();
  std::size_t poll();
  // (the error_code forms of older Boost, still in use)
  std::size_t run(system::error_code & error);
  std::size_t run_one(system::error_code & error);
  std::size_t poll(system::error_code & error);
  void stop();
  bool stopped() const;
  void restart();
  template <class Handler>
  void post(Handler handler);
};
typedef io_context io_service;

namespace placeholders
{
extern const int error;
extern const int bytes_transferred;
}  // namespace placeholders

template <class Clock>
class basic_waitable_timer
{
public:
  typedef typename Clock::duration duration;
  typedef typename Clock::time_point time_point;
  explicit basic_waitable_timer(io_context & io);
  basic_waitable_timer(io_context & io, const time_point & expiry_time);
  basic_waitable_timer(io_context & io, const duration & expiry_time);
  std::size_t cancel();
  time_point expiry() const;
  time_point expires_at() const;
  std::size_t expires_at(const time_point & expiry_time);
  std::size_t expires_after(const duration & expiry_time);
  duration expires_from_now() const;
  std::size_t expires_from_now(const duration & expiry_time);
  void wait();
  template <class WaitHandler>
  void async_wait(WaitHandler && handler);
};
typedef basic_waitable_timer<std::chrono::steady_clock> steady_timer;
typedef basic_waitable_timer<std::chrono::system_clock> system_timer;
typedef basic_waitable_timer<std::chrono::high_resolution_clock>
  high_resolution_timer;

template <class Time>
class basic_deadline_timer
{
public:
  typedef posix_time::time_duration duration_type;
  typedef Time time_type;
  explicit basic_deadline_timer(io_context & io);
  basic_deadline_timer(io_context & io, const time_type & expiry_time);
  basic_deadline_timer(io_context & io, const duration_type & expiry_time);
  std::size_t cancel();
  time_type expires_at() const;
  std::size_t expires_at(const time_type & expiry_time);
  duration_type expires_from_now() const;
  std::size_t expires_from_now(const duration_type & expiry_time);
  void wait();
  template <class WaitHandler>
  void async_wait(WaitHandler && handler);
};
typedef basic_deadline_timer<posix_time::ptime> deadline_timer;
}  // namespace asio
}  // namespace boost

#endif  // RSIA_MODEL_BOOST_ASIO_H
