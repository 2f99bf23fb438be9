// colcon-rsia model of the parts of Boost.Thread that ROS nodes use: mutexes,
// locks, condition variables and boost::thread. Included by the
// <boost/thread*.hpp> model headers.
#ifndef RSIA_MODEL_BOOST_THREAD_H
#define RSIA_MODEL_BOOST_THREAD_H

namespace boost
{

struct defer_lock_t
{
};
struct try_to_lock_t
{
};
struct adopt_lock_t
{
};
constexpr defer_lock_t defer_lock = {};
constexpr try_to_lock_t try_to_lock = {};
constexpr adopt_lock_t adopt_lock = {};

template <class Mutex>
class unique_lock
{
public:
  unique_lock() noexcept;
  explicit unique_lock(Mutex& m);
  unique_lock(Mutex& m, defer_lock_t) noexcept;
  unique_lock(Mutex& m, try_to_lock_t);
  unique_lock(Mutex& m, adopt_lock_t);
  unique_lock(unique_lock&& other) noexcept;
  unique_lock& operator=(unique_lock&& other) noexcept;
  ~unique_lock();

  void lock();
  bool try_lock();
  void unlock();
  bool owns_lock() const noexcept;
  explicit operator bool() const noexcept;
  Mutex* mutex() const noexcept;
};

template <class Mutex>
class lock_guard
{
public:
  explicit lock_guard(Mutex& m);
  lock_guard(Mutex& m, adopt_lock_t);
  lock_guard(const lock_guard&) = delete;
  lock_guard& operator=(const lock_guard&) = delete;
  ~lock_guard();
};

template <class Mutex>
class shared_lock
{
public:
  shared_lock() noexcept;
  explicit shared_lock(Mutex& m);
  ~shared_lock();
  void lock();
  void unlock();
  bool owns_lock() const noexcept;
};

template <class Mutex>
class upgrade_lock
{
public:
  explicit upgrade_lock(Mutex& m);
  ~upgrade_lock();
};

class mutex
{
public:
  mutex();
  mutex(const mutex&) = delete;
  mutex& operator=(const mutex&) = delete;
  ~mutex();
  void lock();
  bool try_lock();
  void unlock();

  typedef unique_lock<mutex> scoped_lock;
  typedef unique_lock<mutex> scoped_try_lock;
};

class recursive_mutex
{
public:
  recursive_mutex();
  recursive_mutex(const recursive_mutex&) = delete;
  recursive_mutex& operator=(const recursive_mutex&) = delete;
  ~recursive_mutex();
  void lock();
  bool try_lock();
  void unlock();

  typedef unique_lock<recursive_mutex> scoped_lock;
  typedef unique_lock<recursive_mutex> scoped_try_lock;
};

class timed_mutex : public mutex
{
};

class shared_mutex
{
public:
  shared_mutex();
  ~shared_mutex();
  void lock();
  bool try_lock();
  void unlock();
  void lock_shared();
  bool try_lock_shared();
  void unlock_shared();
};

class condition_variable
{
public:
  condition_variable();
  ~condition_variable();
  void notify_one() noexcept;
  void notify_all() noexcept;
  void wait(unique_lock<mutex>& lock);
  template <class Predicate>
  void wait(unique_lock<mutex>& lock, Predicate pred);
  template <class Duration>
  bool timed_wait(unique_lock<mutex>& lock, const Duration& d);
};

class condition_variable_any
{
public:
  condition_variable_any();
  ~condition_variable_any();
  void notify_one() noexcept;
  void notify_all() noexcept;
  template <class Lock>
  void wait(Lock& lock);
  template <class Lock, class Predicate>
  void wait(Lock& lock, Predicate pred);
};

typedef condition_variable_any condition;

class thread
{
public:
  class id
  {
  };

  thread() noexcept;
  template <class F, class... Args>
  explicit thread(F f, Args... args);
  thread(thread&& other) noexcept;
  thread& operator=(thread&& other) noexcept;
  thread(const thread&) = delete;
  ~thread();

  void join();
  bool joinable() const noexcept;
  void detach();
  void interrupt();
  bool interruption_requested() const noexcept;
  id get_id() const noexcept;
  static unsigned hardware_concurrency() noexcept;
};

class thread_group
{
public:
  thread_group();
  ~thread_group();
  template <class F>
  thread* create_thread(F f);
  void add_thread(thread* t);
  void join_all();
  void interrupt_all();
  unsigned size() const;
};

namespace this_thread
{

thread::id get_id() noexcept;
void yield() noexcept;
void interruption_point();
template <class Duration>
void sleep(const Duration& d);
template <class Duration>
void sleep_for(const Duration& d);

}  // namespace this_thread

}  // namespace boost

#endif  // RSIA_MODEL_BOOST_THREAD_H
