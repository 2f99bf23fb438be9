// colcon-rsia model of <rclcpp/rclcpp.hpp> (ROS 2, Humble/Jazzy/Rolling):
// declarations of the rclcpp API the analysis recognises, written from the
// documented signatures of the rclcpp API documentation, checked against
// ros2/rclcpp node.hpp, create_*.hpp, rate.hpp, publisher.hpp).
// Every other rclcpp header of the model includes this one.
// RSIA_MODEL_RCLCPP tells the headers ROS 1 and ROS 2 share (tf2_ros/*.h)
// which API to declare.
//
// Where the distros differ the model declares the union that user code of
// every distro resolves against, with the qualified names of the real API:
// - Rate/WallRate are the Jazzy+ classes (Humble: aliases of GenericRate);
//   GenericRate<Clock> is kept (Humble, deprecated in Jazzy) and ROSRate
//   (Rolling) is declared too;
// - create_service/create_client take a QoS (all) or the deprecated
//   rmw_qos_profile_t (Humble, Jazzy);
// - Node::create_timer and the free create_timer(clock, period, ...) form
//   exist from Jazzy on; create_wall_timer gains `autostart` in Jazzy.
#ifndef RSIA_MODEL_RCLCPP_RCLCPP_HPP
#define RSIA_MODEL_RCLCPP_RCLCPP_HPP
#define RSIA_MODEL_RCLCPP 1

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include <rsia_model/message.h>
#include <rcl_interfaces/msg/parameter.hpp>
#include <rcl_interfaces/msg/parameter_descriptor.hpp>
#include <rcl_interfaces/msg/parameter_event.hpp>
#include <rcl_interfaces/msg/parameter_value.hpp>
#include <rcl_interfaces/msg/set_parameters_result.hpp>
#include <rcl_interfaces/msg/list_parameters_result.hpp>

// the smart pointer aliases and factories of rclcpp/macros.hpp
#define RCLCPP_SHARED_PTR_DEFINITIONS(...) \
  using SharedPtr = std::shared_ptr<__VA_ARGS__>; \
  using ConstSharedPtr = std::shared_ptr<const __VA_ARGS__>; \
  template<typename ... RsiaArgs> \
  static std::shared_ptr<__VA_ARGS__> make_shared(RsiaArgs && ... args);
#define RCLCPP_WEAK_PTR_DEFINITIONS(...) \
  using WeakPtr = std::weak_ptr<__VA_ARGS__>; \
  using ConstWeakPtr = std::weak_ptr<const __VA_ARGS__>;
#define RCLCPP_UNIQUE_PTR_DEFINITIONS(...) \
  using UniquePtr = std::unique_ptr<__VA_ARGS__>; \
  template<typename ... RsiaArgs> \
  static std::unique_ptr<__VA_ARGS__> make_unique(RsiaArgs && ... args);
#define RCLCPP_SMART_PTR_DEFINITIONS(...) \
  RCLCPP_SHARED_PTR_DEFINITIONS(__VA_ARGS__) \
  RCLCPP_WEAK_PTR_DEFINITIONS(__VA_ARGS__) \
  RCLCPP_UNIQUE_PTR_DEFINITIONS(__VA_ARGS__)
#define RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(...) \
  using SharedPtr = std::shared_ptr<__VA_ARGS__>; \
  using ConstSharedPtr = std::shared_ptr<const __VA_ARGS__>; \
  RCLCPP_WEAK_PTR_DEFINITIONS(__VA_ARGS__) \
  using UniquePtr = std::unique_ptr<__VA_ARGS__>;
#define RCLCPP_SMART_PTR_ALIASES_ONLY(...) \
  using SharedPtr = std::shared_ptr<__VA_ARGS__>; \
  using ConstSharedPtr = std::shared_ptr<const __VA_ARGS__>; \
  using WeakPtr = std::weak_ptr<__VA_ARGS__>; \
  using ConstWeakPtr = std::weak_ptr<const __VA_ARGS__>; \
  using UniquePtr = std::unique_ptr<__VA_ARGS__>;
#define RCLCPP_DISABLE_COPY(...) \
  __VA_ARGS__(const __VA_ARGS__ &) = delete; \
  __VA_ARGS__ & operator=(const __VA_ARGS__ &) = delete;
#define RCLCPP_PUBLIC
#define RCLCPP_LOCAL
#define RCUTILS_WARN_UNUSED
#define RCUTILS_UNUSED(x) (void)(x)

struct rmw_request_id_t
{
  int64_t sequence_number;
};

// the C layers under rclcpp (rcl, rmw, rcutils) that node code uses
// directly: return codes, QoS policies, serialized messages, logging
typedef int32_t rcl_ret_t;
typedef int32_t rmw_ret_t;
#define RCL_RET_OK 0
#define RCL_RET_ERROR 1
// rcl/arguments.h: the flags of the ROS command line (a launcher or a
// manager composes them: `args.push_back(RCL_ROS_ARGS_FLAG)`)
#define RCL_ROS_ARGS_FLAG "--ros-args"
#define RCL_ROS_ARGS_EXPLICIT_END_TOKEN "--"
#define RCL_PARAM_FLAG "--param"
#define RCL_SHORT_PARAM_FLAG "-p"
#define RCL_PARAM_FILE_FLAG "--params-file"
#define RCL_REMAP_FLAG "--remap"
#define RCL_SHORT_REMAP_FLAG "-r"
#define RCL_ENCLAVE_FLAG "--enclave"
#define RCL_SHORT_ENCLAVE_FLAG "-e"
#define RCL_LOG_LEVEL_FLAG "--log-level"
#define RMW_RET_OK 0
#define RMW_RET_ERROR 1
enum rmw_qos_reliability_policy_t
{
  RMW_QOS_POLICY_RELIABILITY_SYSTEM_DEFAULT,
  RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT,
  RMW_QOS_POLICY_RELIABILITY_UNKNOWN,
  RMW_QOS_POLICY_RELIABILITY_BEST_AVAILABLE
};
enum rmw_qos_history_policy_t
{
  RMW_QOS_POLICY_HISTORY_SYSTEM_DEFAULT,
  RMW_QOS_POLICY_HISTORY_KEEP_LAST,
  RMW_QOS_POLICY_HISTORY_KEEP_ALL,
  RMW_QOS_POLICY_HISTORY_UNKNOWN
};
enum rmw_qos_durability_policy_t
{
  RMW_QOS_POLICY_DURABILITY_SYSTEM_DEFAULT,
  RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL,
  RMW_QOS_POLICY_DURABILITY_VOLATILE,
  RMW_QOS_POLICY_DURABILITY_UNKNOWN,
  RMW_QOS_POLICY_DURABILITY_BEST_AVAILABLE
};
enum rmw_qos_liveliness_policy_t
{
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_AUTOMATIC,
  RMW_QOS_POLICY_LIVELINESS_MANUAL_BY_NODE,
  RMW_QOS_POLICY_LIVELINESS_MANUAL_BY_TOPIC,
  RMW_QOS_POLICY_LIVELINESS_UNKNOWN,
  RMW_QOS_POLICY_LIVELINESS_BEST_AVAILABLE
};
struct rmw_time_t
{
  std::uint64_t sec;
  std::uint64_t nsec;
};
#define RMW_DURATION_DEFAULT {0, 0}
#define RMW_QOS_DEADLINE_DEFAULT RMW_DURATION_DEFAULT
#define RMW_QOS_LIFESPAN_DEFAULT RMW_DURATION_DEFAULT
#define RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT RMW_DURATION_DEFAULT
// all nine fields: code writes a profile as an aggregate of them
struct rmw_qos_profile_t
{
  rmw_qos_history_policy_t history;
  std::size_t depth;
  rmw_qos_reliability_policy_t reliability;
  rmw_qos_durability_policy_t durability;
  rmw_time_t deadline;
  rmw_time_t lifespan;
  rmw_qos_liveliness_policy_t liveliness;
  rmw_time_t liveliness_lease_duration;
  bool avoid_ros_namespace_conventions;
};
struct rcutils_allocator_t
{
  void * state;
};
rcutils_allocator_t rcutils_get_default_allocator();
bool rcutils_cli_option_exist(char ** begin, char ** end, const char * option);
char * rcutils_cli_get_option(char ** begin, char ** end, const char * option);
extern const rmw_qos_profile_t rmw_qos_profile_default;
extern const rmw_qos_profile_t rmw_qos_profile_services_default;
extern const rmw_qos_profile_t rmw_qos_profile_sensor_data;
extern const rmw_qos_profile_t rmw_qos_profile_parameters;
extern const rmw_qos_profile_t rmw_qos_profile_system_default;

struct rcl_serialized_message_t
{
  uint8_t * buffer;
  std::size_t buffer_length;
  std::size_t buffer_capacity;
  rcutils_allocator_t allocator;
};
typedef rcl_serialized_message_t rmw_serialized_message_t;
rmw_serialized_message_t rmw_get_zero_initialized_serialized_message();
rmw_ret_t rmw_serialized_message_init(
  rmw_serialized_message_t * msg, std::size_t size,
  const rcutils_allocator_t * allocator);
rmw_ret_t rmw_serialized_message_resize(
  rmw_serialized_message_t * msg, std::size_t size);
rmw_ret_t rmw_serialized_message_fini(rmw_serialized_message_t * msg);
using rmw_serialized_message_t = rcl_serialized_message_t;

// rcutils/time.h, rcl/time.h: nanoseconds
typedef int64_t rcutils_time_point_value_t;
typedef int64_t rcutils_duration_value_t;
typedef rcutils_time_point_value_t rcl_time_point_value_t;
typedef rcutils_duration_value_t rcl_duration_value_t;

enum rcl_clock_type_t
{
  RCL_CLOCK_UNINITIALIZED = 0,
  RCL_ROS_TIME,
  RCL_SYSTEM_TIME,
  RCL_STEADY_TIME
};

// rcl's timer, which rclcpp::TimerBase wraps (rcl/timer.h)
typedef struct rcl_timer_s rcl_timer_t;

namespace rclcpp
{

// rclcpp/context.hpp: the handles are rclcpp's, not the context's
// (`std::unique_ptr<rclcpp::PreShutdownCallbackHandle> handle_`)
struct ShutdownCallbackHandle
{
  using ShutdownCallbackType = std::function<void ()>;
};
using OnShutdownCallbackHandle = ShutdownCallbackHandle;
using PreShutdownCallbackHandle = ShutdownCallbackHandle;

class Context
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Context)
  using OnShutdownCallback = ShutdownCallbackHandle::ShutdownCallbackType;
  using PreShutdownCallback = ShutdownCallbackHandle::ShutdownCallbackType;
  bool is_valid() const;
  bool shutdown(const std::string & reason);
  virtual OnShutdownCallbackHandle add_on_shutdown_callback(
    OnShutdownCallback callback);
  virtual bool remove_on_shutdown_callback(
    const OnShutdownCallbackHandle & callback_handle);
  virtual PreShutdownCallbackHandle add_pre_shutdown_callback(
    PreShutdownCallback callback);
  virtual bool remove_pre_shutdown_callback(
    const PreShutdownCallbackHandle & callback_handle);
};

namespace exceptions
{
class RCLErrorBase
{
public:
  virtual ~RCLErrorBase() {}
  int ret;
  std::string message;
  std::string file;
  size_t line;
  std::string formatted_message;
};
class RCLError : public RCLErrorBase, public std::runtime_error
{
public:
  RCLError(const RCLErrorBase & base_exc, const std::string & prefix);
};
class InvalidParameterValueException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};
class ParameterNotDeclaredException : public std::runtime_error
{
  using std::runtime_error::runtime_error;
};
}  // namespace exceptions

class InitOptions
{
public:
  InitOptions();
};

enum class SignalHandlerOptions { All, SigInt, SigTerm, None };

void init(int argc, char const * const * argv,
          const InitOptions & init_options = InitOptions(),
          SignalHandlerOptions signal_handler_options = SignalHandlerOptions::All);
std::vector<std::string> init_and_remove_ros_arguments(
  int argc, char const * const * argv,
  const InitOptions & init_options = InitOptions());
std::vector<std::string> remove_ros_arguments(int argc, char const * const * argv);
bool shutdown(Context::SharedPtr context = nullptr,
              const std::string & reason = "user called rclcpp::shutdown()");
bool ok(Context::SharedPtr context = nullptr);
void on_shutdown(std::function<void()> callback,
                 Context::SharedPtr context = nullptr);
bool sleep_for(const std::chrono::nanoseconds & nanoseconds,
               Context::SharedPtr context = nullptr);

namespace contexts
{
Context::SharedPtr get_global_default_context();
}  // namespace contexts

class Logger
{
public:
  enum class Level { Unset = 0, Debug = 10, Info = 20, Warn = 30, Error = 40, Fatal = 50 };
  Logger get_child(const std::string & suffix);
  const char * get_name() const;
  void set_level(Level level);
  Level get_effective_level() const;
};
Logger get_logger(const std::string & name);

class Duration
{
public:
  Duration(int32_t seconds, uint32_t nanoseconds);
  explicit Duration(std::chrono::nanoseconds nanoseconds);
  template<class Rep, class Period>
  Duration(const std::chrono::duration<Rep, Period> & duration);
  Duration(const Duration & rhs);
  // from builtin_interfaces::msg::Duration (implicit, like the real one),
  // also a message stand-in's field holding one
  template<class M, typename std::enable_if<
      std::is_base_of<rsia_model::Fields, M>::value ||
      std::is_base_of<rsia_model::Any, M>::value, int>::type = 0>
  Duration(const M & duration_msg);
  Duration & operator=(const Duration & rhs);
  static Duration max();
  static Duration from_seconds(double seconds);
  static Duration from_nanoseconds(int64_t nanoseconds);
  double seconds() const;
  int64_t nanoseconds() const;
  template<class DurationT>
  DurationT to_chrono() const;
  Duration operator+(const Duration & rhs) const;
  Duration operator-(const Duration & rhs) const;
  Duration operator*(double scale) const;
  bool operator==(const Duration & rhs) const;
  bool operator!=(const Duration & rhs) const;
  bool operator<(const Duration & rhs) const;
  bool operator<=(const Duration & rhs) const;
  bool operator>(const Duration & rhs) const;
  bool operator>=(const Duration & rhs) const;
  // to builtin_interfaces::msg::Duration (a message), as the real one; to
  // anything, `duration * i` would tie with the built-in `*`
  template<class M, typename std::enable_if<
      std::is_base_of<rsia_model::Fields, M>::value, int>::type = 0>
  operator M() const;
};

template<class T>
struct RsiaIsChronoDuration : std::false_type {};
template<class Rep, class Period>
struct RsiaIsChronoDuration<std::chrono::duration<Rep, Period>>
  : std::true_type {};

class Time
{
public:
  Time(int32_t seconds, uint32_t nanoseconds,
       rcl_clock_type_t clock_type = RCL_SYSTEM_TIME);
  explicit Time(int64_t nanoseconds = 0,
                rcl_clock_type_t clock_type = RCL_SYSTEM_TIME);
  // from builtin_interfaces::msg::Time (implicit, like the real one); not
  // from a std::chrono duration, which converts to a Duration only
  // (`now() - std::chrono::nanoseconds(n)` would tie), nor from a
  // std::optional<Time> (`cond ? now() : optional_stamp` would tie)
  template<class M, typename std::enable_if<
      !RsiaIsChronoDuration<M>::value &&
      !rsia_model::is_optional<M>::value, int>::type = 0>
  Time(const M & time_msg, rcl_clock_type_t clock_type = RCL_ROS_TIME);
  Time(const Time & rhs);
  Time & operator=(const Time & rhs);
  static Time max(rcl_clock_type_t clock_type = RCL_SYSTEM_TIME);
  double seconds() const;
  int64_t nanoseconds() const;
  rcl_clock_type_t get_clock_type() const;
  Duration operator-(const Time & rhs) const;
  // `now() - msg.header.stamp`: a message stand-in converts to a Duration as
  // well as to a Time, so the two operators above would tie (M&&: as
  // exact as the catch-all operators of rsia_model::Any, which Time
  // converts to)
  template<class M, class = typename std::decay<M>::type::rsia_model_message_tag>
  Duration operator-(M && time_msg) const;
  Time operator+(const Duration & rhs) const;
  Time operator-(const Duration & rhs) const;
  Time & operator+=(const Duration & rhs);
  bool operator==(const Time & rhs) const;
  bool operator!=(const Time & rhs) const;
  bool operator<(const Time & rhs) const;
  bool operator<=(const Time & rhs) const;
  bool operator>(const Time & rhs) const;
  bool operator>=(const Time & rhs) const;
  // to builtin_interfaces::msg::Time (a message), as the real one
  template<class M, typename std::enable_if<
      std::is_base_of<rsia_model::Fields, M>::value, int>::type = 0>
  operator M() const;
};

class Clock
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Clock)
  explicit Clock(rcl_clock_type_t clock_type = RCL_SYSTEM_TIME);
  Time now() const;
  // Jazzy+
  bool sleep_until(Time until, Context::SharedPtr context = nullptr);
  bool sleep_for(Duration rel_time, Context::SharedPtr context = nullptr);
  bool ros_time_is_active();
  rcl_clock_type_t get_clock_type() const;
  // Iron+
  bool started();
  bool wait_until_started(Context::SharedPtr context = nullptr);
  bool wait_until_started(
    const Duration & timeout, Context::SharedPtr context = nullptr,
    const Duration & wait_tick_ns = Duration(0, 10000000));
};

// rclcpp/qos.hpp
struct KeepLast
{
  explicit KeepLast(std::size_t depth);
};

struct KeepAll
{
  KeepAll();
};

struct QoSInitialization
{
  QoSInitialization(int history_policy, std::size_t depth);
  static QoSInitialization from_rmw(const rmw_qos_profile_t & rmw_qos);
};

// rclcpp/qos.hpp (Galactic+): the policies as rclcpp's own enums
enum class HistoryPolicy { KeepLast, KeepAll, SystemDefault, Unknown };
enum class ReliabilityPolicy { BestEffort, Reliable, SystemDefault, BestAvailable, Unknown };
enum class DurabilityPolicy { Volatile, TransientLocal, SystemDefault, BestAvailable, Unknown };
enum class LivelinessPolicy { Automatic, ManualByTopic, SystemDefault, BestAvailable, Unknown };

class QoS
{
public:
  QoS(const QoSInitialization & qos_initialization,
      const rmw_qos_profile_t & initial_profile = rmw_qos_profile_default);
  QoS(std::size_t history_depth);
  QoS(const KeepLast & keep_last,
      const rmw_qos_profile_t & initial_profile = rmw_qos_profile_default);
  QoS(const KeepAll & keep_all,
      const rmw_qos_profile_t & initial_profile = rmw_qos_profile_default);
  rmw_qos_profile_t & get_rmw_qos_profile();
  const rmw_qos_profile_t & get_rmw_qos_profile() const;
  QoS & history(rmw_qos_history_policy_t history);
  QoS & reliability(rmw_qos_reliability_policy_t reliability);
  QoS & durability(rmw_qos_durability_policy_t durability);
  QoS & history(HistoryPolicy history);
  QoS & reliability(ReliabilityPolicy reliability);
  QoS & durability(DurabilityPolicy durability);
  QoS & liveliness(LivelinessPolicy liveliness);
  QoS & keep_last(std::size_t depth);
  QoS & keep_all();
  QoS & reliable();
  QoS & best_effort();
  QoS & durability_volatile();
  QoS & transient_local();
  QoS & deadline(const Duration & deadline);
  QoS & lifespan(const Duration & lifespan);
  std::size_t depth() const;
};

class SensorDataQoS : public QoS
{
public:
  explicit SensorDataQoS(
    const QoSInitialization & qos_initialization = QoSInitialization(0, 5));
};

class SystemDefaultsQoS : public QoS
{
public:
  explicit SystemDefaultsQoS(
    const QoSInitialization & qos_initialization = QoSInitialization(0, 0));
};

class ServicesQoS : public QoS
{
public:
  explicit ServicesQoS(
    const QoSInitialization & qos_initialization = QoSInitialization(0, 10));
};

class ParametersQoS : public QoS
{
public:
  explicit ParametersQoS(
    const QoSInitialization & qos_initialization = QoSInitialization(0, 1000));
};

class ParameterEventsQoS : public QoS
{
public:
  explicit ParameterEventsQoS(
    const QoSInitialization & qos_initialization = QoSInitialization(0, 1000));
};

class RosoutQoS : public QoS
{
public:
  explicit RosoutQoS(
    const QoSInitialization & qos_initialization = QoSInitialization(0, 1000));
};

class ClockQoS : public QoS
{
public:
  explicit ClockQoS(
    const QoSInitialization & qos_initialization = QoSInitialization(0, 1));
};

// rclcpp/callback_group.hpp
enum class CallbackGroupType { MutuallyExclusive, Reentrant };

class CallbackGroup
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(CallbackGroup)
  CallbackGroupType type() const;
};

namespace callback_group
{
using CallbackGroupType = rclcpp::CallbackGroupType;
using CallbackGroup = rclcpp::CallbackGroup;
}  // namespace callback_group

// rclcpp/parameter.hpp, parameter_value.hpp
enum ParameterType : uint8_t
{
  PARAMETER_NOT_SET = 0,
  PARAMETER_BOOL,
  PARAMETER_INTEGER,
  PARAMETER_DOUBLE,
  PARAMETER_STRING,
  PARAMETER_BYTE_ARRAY,
  PARAMETER_BOOL_ARRAY,
  PARAMETER_INTEGER_ARRAY,
  PARAMETER_DOUBLE_ARRAY,
  PARAMETER_STRING_ARRAY,
};

class ParameterValue
{
public:
  ParameterValue();
  explicit ParameterValue(bool bool_value);
  explicit ParameterValue(int int_value);
  explicit ParameterValue(int64_t int_value);
  explicit ParameterValue(float double_value);
  explicit ParameterValue(double double_value);
  explicit ParameterValue(const std::string & string_value);
  explicit ParameterValue(const char * string_value);
  explicit ParameterValue(const std::vector<bool> & bool_array_value);
  explicit ParameterValue(const std::vector<int64_t> & int_array_value);
  explicit ParameterValue(const std::vector<double> & double_array_value);
  explicit ParameterValue(const std::vector<std::string> & string_array_value);
  ParameterType get_type() const;
  template<class T>
  T get() const;
};

class Parameter
{
public:
  Parameter();
  explicit Parameter(const std::string & name);
  Parameter(const std::string & name, const ParameterValue & value);
  template<class ValueTypeT>
  Parameter(const std::string & name, ValueTypeT value);
  ParameterType get_type() const;
  std::string get_type_name() const;
  const std::string & get_name() const;
  const ParameterValue & get_parameter_value() const;
  template<class T>
  T get_value() const;
  bool as_bool() const;
  int64_t as_int() const;
  double as_double() const;
  const std::string & as_string() const;
  const std::vector<uint8_t> & as_byte_array() const;
  const std::vector<bool> & as_bool_array() const;
  const std::vector<int64_t> & as_integer_array() const;
  const std::vector<double> & as_double_array() const;
  const std::vector<std::string> & as_string_array() const;
  std::string value_to_string() const;
  static Parameter from_parameter_msg(const rcl_interfaces::msg::Parameter & parameter);
  rcl_interfaces::msg::Parameter to_parameter_msg() const;
  rcl_interfaces::msg::ParameterValue get_value_message() const;
};

// rclcpp/node_options.hpp
class NodeOptions
{
public:
  NodeOptions();
  NodeOptions(const NodeOptions & other);
  NodeOptions & operator=(const NodeOptions & other);
  Context::SharedPtr context() const;
  NodeOptions & context(Context::SharedPtr context);
  const std::vector<std::string> & arguments() const;
  NodeOptions & arguments(const std::vector<std::string> & arguments);
  std::vector<Parameter> & parameter_overrides();
  const std::vector<Parameter> & parameter_overrides() const;
  NodeOptions & parameter_overrides(
    const std::vector<Parameter> & parameter_overrides);
  template<class ParameterT>
  NodeOptions & append_parameter_override(
    const std::string & name, const ParameterT & value);
  bool use_global_arguments() const;
  NodeOptions & use_global_arguments(bool use_global_arguments);
  bool enable_rosout() const;
  NodeOptions & enable_rosout(bool enable_rosout);
  bool use_intra_process_comms() const;
  NodeOptions & use_intra_process_comms(bool use_intra_process_comms);
  bool enable_topic_statistics() const;
  NodeOptions & enable_topic_statistics(bool enable_topic_statistics);
  bool start_parameter_services() const;
  NodeOptions & start_parameter_services(bool start_parameter_services);
  bool start_parameter_event_publisher() const;
  NodeOptions & start_parameter_event_publisher(
    bool start_parameter_event_publisher);
  const QoS & parameter_event_qos() const;
  NodeOptions & parameter_event_qos(const QoS & parameter_event_qos);
  const QoS & clock_qos() const;
  NodeOptions & clock_qos(const QoS & clock_qos);
  bool use_clock_thread() const;
  NodeOptions & use_clock_thread(bool use_clock_thread);
  bool allow_undeclared_parameters() const;
  NodeOptions & allow_undeclared_parameters(bool allow_undeclared_parameters);
  bool automatically_declare_parameters_from_overrides() const;
  NodeOptions & automatically_declare_parameters_from_overrides(
    bool automatically_declare_parameters_from_overrides);
  // Jazzy+
  bool enable_logger_service() const;
  NodeOptions & enable_logger_service(bool enable_log_service);
};

// event_handler.hpp (qos_event.hpp before Iron): the status of QoS events
struct QOSEventInfo
{
  int32_t total_count;
  int32_t total_count_change;
  int32_t current_count;
  int32_t current_count_change;
  int32_t alive_count;
  int32_t alive_count_change;
  int32_t not_alive_count;
  int32_t not_alive_count_change;
  int32_t last_policy_kind;
};
using QOSDeadlineOfferedInfo = QOSEventInfo;
using QOSDeadlineRequestedInfo = QOSEventInfo;
using QOSLivelinessLostInfo = QOSEventInfo;
using QOSLivelinessChangedInfo = QOSEventInfo;
using QOSOfferedIncompatibleQoSInfo = QOSEventInfo;
using QOSRequestedIncompatibleQoSInfo = QOSEventInfo;
using QOSMessageLostInfo = QOSEventInfo;
using IncompatibleTypeInfo = QOSEventInfo;
using MatchedInfo = QOSEventInfo;

struct PublisherEventCallbacks
{
  std::function<void(QOSDeadlineOfferedInfo &)> deadline_callback;
  std::function<void(QOSLivelinessLostInfo &)> liveliness_callback;
  std::function<void(QOSOfferedIncompatibleQoSInfo &)> incompatible_qos_callback;
  std::function<void(IncompatibleTypeInfo &)> incompatible_type_callback;
  std::function<void(MatchedInfo &)> matched_callback;
};

struct SubscriptionEventCallbacks
{
  std::function<void(QOSDeadlineRequestedInfo &)> deadline_callback;
  std::function<void(QOSLivelinessChangedInfo &)> liveliness_callback;
  std::function<void(QOSRequestedIncompatibleQoSInfo &)> incompatible_qos_callback;
  std::function<void(IncompatibleTypeInfo &)> incompatible_type_callback;
  std::function<void(QOSMessageLostInfo &)> message_lost_callback;
  std::function<void(MatchedInfo &)> matched_callback;
};

// qos_overriding_options.hpp: QoS policies overridable by parameters
enum class QosPolicyKind
{
  AvoidRosNamespaceConventions, Deadline, Depth, Durability, History,
  Lifespan, Liveliness, LivelinessLeaseDuration, Reliability, Invalid
};
using QosCallbackResult = rcl_interfaces::msg::SetParametersResult;
using QosCallback = std::function<QosCallbackResult(const QoS &)>;
class QosOverridingOptions
{
public:
  QosOverridingOptions();
  QosOverridingOptions(
    std::initializer_list<QosPolicyKind> policy_kinds,
    QosCallback validation_callback = nullptr, std::string id = {});
  static QosOverridingOptions with_default_policies(
    QosCallback validation_callback = nullptr, std::string id = {});
};

enum class IntraProcessSetting { Enable, Disable, NodeDefault };

// publisher_options.hpp, subscription_options.hpp
template<class AllocatorT = std::allocator<void>>
class PublisherOptionsWithAllocator
{
public:
  PublisherOptionsWithAllocator();
  PublisherEventCallbacks event_callbacks;
  bool use_default_callbacks = true;
  IntraProcessSetting use_intra_process_comm = IntraProcessSetting::NodeDefault;
  QosOverridingOptions qos_overriding_options;
  CallbackGroup::SharedPtr callback_group;
  std::shared_ptr<AllocatorT> allocator;
};
using PublisherOptions = PublisherOptionsWithAllocator<std::allocator<void>>;

template<class AllocatorT = std::allocator<void>>
class SubscriptionOptionsWithAllocator
{
public:
  SubscriptionOptionsWithAllocator();
  SubscriptionEventCallbacks event_callbacks;
  bool use_default_callbacks = true;
  IntraProcessSetting use_intra_process_comm = IntraProcessSetting::NodeDefault;
  QosOverridingOptions qos_overriding_options;
  CallbackGroup::SharedPtr callback_group;
  bool ignore_local_publications = false;
  std::shared_ptr<AllocatorT> allocator;
};
using SubscriptionOptions =
  SubscriptionOptionsWithAllocator<std::allocator<void>>;

// serialized_message.hpp, message_info.hpp, loaned_message.hpp
class SerializedMessage
{
public:
  SerializedMessage();
  explicit SerializedMessage(std::size_t initial_capacity);
  SerializedMessage(const SerializedMessage & other);
  SerializedMessage & operator=(const SerializedMessage & other);
  rcl_serialized_message_t & get_rcl_serialized_message();
  const rcl_serialized_message_t & get_rcl_serialized_message() const;
  std::size_t size() const;
  std::size_t capacity() const;
  void reserve(std::size_t capacity);
};

template<class MessageT>
class Serialization
{
public:
  Serialization();
  void serialize_message(const MessageT * ros_message,
                         SerializedMessage * serialized_message) const;
  void deserialize_message(const SerializedMessage * serialized_message,
                           MessageT * ros_message) const;
};

class MessageInfo
{
public:
  MessageInfo();
};

template<class MessageT, class AllocatorT = std::allocator<void>>
class LoanedMessage
{
public:
  LoanedMessage(LoanedMessage && other);
  LoanedMessage & operator=(LoanedMessage && other) = delete;
  virtual ~LoanedMessage();
  bool is_valid() const;
  MessageT & get() const;
  std::unique_ptr<MessageT, std::function<void(MessageT *)>> release();
};

// publisher_base.hpp, publisher.hpp
class PublisherBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(PublisherBase)
  virtual ~PublisherBase();
  const char * get_topic_name() const;
  std::size_t get_queue_size() const;
  template<typename DurationRepT = int64_t, typename DurationT = std::milli>
  bool wait_for_all_acked(
    std::chrono::duration<DurationRepT, DurationT> timeout =
    std::chrono::duration<DurationRepT, DurationT>(-1)) const;
  std::size_t get_subscription_count() const;
  std::size_t get_intra_process_subscription_count() const;
  bool can_loan_messages() const;
  QoS get_actual_qos() const;
  bool assert_liveliness() const;
};

template<class MessageT, class AllocatorT = std::allocator<void>>
class Publisher : public PublisherBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Publisher)
  using ROSMessageType = MessageT;
  using PublishedType = MessageT;
  using MessageUniquePtr = std::unique_ptr<MessageT>;
  using MessageSharedPtr = std::shared_ptr<const MessageT>;

  virtual LoanedMessage<MessageT, AllocatorT> borrow_loaned_message();
  // publish(std::unique_ptr<T, Deleter>) and publish(const T &) are
  // templates constrained to the ROS (or adapted) type in the real header
  virtual void publish(std::unique_ptr<MessageT> msg);
  virtual void publish(const MessageT & msg);
  void publish(const rcl_serialized_message_t & serialized_msg);
  void publish(const SerializedMessage & serialized_msg);
  void publish(LoanedMessage<MessageT, AllocatorT> && loaned_msg);
};

class GenericPublisher : public PublisherBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericPublisher)
  void publish(const SerializedMessage & message);
  void publish_as_loaned_msg(const SerializedMessage & message);
};

// subscription_base.hpp, subscription.hpp, generic_subscription.hpp
class SubscriptionBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(SubscriptionBase)
  virtual ~SubscriptionBase();
  const char * get_topic_name() const;
  std::size_t get_publisher_count() const;
  QoS get_actual_qos() const;
};

template<class MessageT, class AllocatorT = std::allocator<void>>
class Subscription : public SubscriptionBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Subscription)
};

class GenericSubscription : public SubscriptionBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericSubscription)
};

// timer.hpp
class TimerInfo
{
public:
  Time expected_call_time;
  Time actual_call_time;
};

class TimerBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(TimerBase)
  virtual ~TimerBase();
  std::shared_ptr<const rcl_timer_t> get_timer_handle();
  void cancel();
  bool is_canceled();
  void reset();
  std::chrono::nanoseconds time_until_trigger();
  bool is_ready();
};

template<class FunctorT>
class GenericTimer : public TimerBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericTimer)
  GenericTimer(
    std::shared_ptr<Clock> clock, std::chrono::nanoseconds period,
    FunctorT && callback, std::shared_ptr<Context> context,
    bool autostart = true);
};

template<class FunctorT>
class WallTimer : public GenericTimer<FunctorT>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(WallTimer)
  WallTimer(
    std::chrono::nanoseconds period, FunctorT && callback,
    std::shared_ptr<Context> context, bool autostart = true);
};

// service.hpp, client.hpp
class ServiceBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(ServiceBase)
  virtual ~ServiceBase();
  const char * get_service_name();
};

template<class ServiceT>
class Service : public ServiceBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Service)
  using CallbackType = std::function<void(
        const std::shared_ptr<typename ServiceT::Request>,
        std::shared_ptr<typename ServiceT::Response>)>;
  using CallbackWithHeaderType = std::function<void(
        const std::shared_ptr<rmw_request_id_t>,
        const std::shared_ptr<typename ServiceT::Request>,
        std::shared_ptr<typename ServiceT::Response>)>;
  void send_response(rmw_request_id_t & req_id,
                     typename ServiceT::Response & response);
};

enum class FutureReturnCode { SUCCESS, INTERRUPTED, TIMEOUT };

namespace detail
{
// what a client's future of a request and the one of a request with a
// callback share (Humble+)
template<class FutureT>
struct FutureAndRequestId
{
  FutureT future;
  int64_t request_id;
  operator FutureT &();
  decltype(std::declval<FutureT &>().get()) get();
  bool valid() const noexcept;
  void wait() const;
  template<class RepT, class RatioT>
  std::future_status wait_for(
    const std::chrono::duration<RepT, RatioT> & timeout_duration) const;
  template<class ClockT, class DurationT>
  std::future_status wait_until(
    const std::chrono::time_point<ClockT, DurationT> & timeout_time) const;
};
}  // namespace detail

class ClientBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(ClientBase)
  virtual ~ClientBase();
  const char * get_service_name() const;
  bool service_is_ready() const;
  template<class RepT = int64_t, class RatioT = std::milli>
  bool wait_for_service(
    std::chrono::duration<RepT, RatioT> timeout =
    std::chrono::duration<RepT, RatioT>(-1));
};

template<class ServiceT>
class Client : public ClientBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Client)
  using Request = typename ServiceT::Request;
  using Response = typename ServiceT::Response;
  using SharedRequest = std::shared_ptr<Request>;
  using SharedResponse = std::shared_ptr<Response>;
  using Promise = std::promise<SharedResponse>;
  using SharedPromise = std::shared_ptr<Promise>;
  using Future = std::future<SharedResponse>;
  using SharedFuture = std::shared_future<SharedResponse>;
  using CallbackType = std::function<void(SharedFuture)>;

  struct FutureAndRequestId : detail::FutureAndRequestId<Future>
  {
    SharedFuture share() noexcept;
  };
  struct SharedFutureAndRequestId : detail::FutureAndRequestId<SharedFuture>
  {
  };

  FutureAndRequestId async_send_request(SharedRequest request);
  template<class CallbackT>
  SharedFutureAndRequestId async_send_request(
    SharedRequest request, CallbackT && cb);
  bool remove_pending_request(int64_t request_id);
  std::size_t prune_pending_requests();
};

class GenericClient : public ClientBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericClient)
};

class Event
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Event)
  bool set();
  bool check();
};

// node_interfaces/*.hpp
namespace node_interfaces
{
class NodeBaseInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeBaseInterface)
  virtual ~NodeBaseInterface();
  virtual const char * get_name() const = 0;
  virtual std::atomic_bool & get_associated_with_executor_atomic() = 0;
  virtual const char * get_namespace() const = 0;
  virtual const char * get_fully_qualified_name() const = 0;
  virtual Context::SharedPtr get_context() = 0;
  virtual CallbackGroup::SharedPtr create_callback_group(
    CallbackGroupType group_type,
    bool automatically_add_to_executor_with_node = true) = 0;
  virtual CallbackGroup::SharedPtr get_default_callback_group() = 0;
};
class NodeClockInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeClockInterface)
  virtual ~NodeClockInterface();
  virtual Clock::SharedPtr get_clock() = 0;
};
class NodeGraphInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeGraphInterface)
  virtual ~NodeGraphInterface();
  virtual std::size_t count_publishers(const std::string & topic_name) const = 0;
  virtual std::size_t count_subscribers(const std::string & topic_name) const = 0;
};
class NodeLoggingInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeLoggingInterface)
  virtual ~NodeLoggingInterface();
  virtual Logger get_logger() const = 0;
};
class NodeTimersInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeTimersInterface)
  virtual ~NodeTimersInterface();
  virtual void add_timer(TimerBase::SharedPtr timer,
                         CallbackGroup::SharedPtr callback_group) = 0;
};
class NodeTopicsInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeTopicsInterface)
  virtual ~NodeTopicsInterface();
  virtual std::string resolve_topic_name(
    const std::string & name, bool only_expand = false) const = 0;
};
class NodeServicesInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeServicesInterface)
  virtual ~NodeServicesInterface();
};
class NodeWaitablesInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeWaitablesInterface)
  virtual ~NodeWaitablesInterface();
};
class NodeTimeSourceInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeTimeSourceInterface)
  virtual ~NodeTimeSourceInterface();
};
class OnSetParametersCallbackHandle
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(OnSetParametersCallbackHandle)
  using OnSetParametersCallbackType =
    std::function<rcl_interfaces::msg::SetParametersResult(
        const std::vector<rclcpp::Parameter> &)>;
  OnSetParametersCallbackType callback;
};
class PreSetParametersCallbackHandle
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(PreSetParametersCallbackHandle)
  using PreSetParametersCallbackType =
    std::function<void(std::vector<rclcpp::Parameter> &)>;
  PreSetParametersCallbackType callback;
};
class PostSetParametersCallbackHandle
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(PostSetParametersCallbackHandle)
  using PostSetParametersCallbackType =
    std::function<void(const std::vector<rclcpp::Parameter> &)>;
  PostSetParametersCallbackType callback;
};
class NodeParametersInterface
{
public:
  RCLCPP_SMART_PTR_ALIASES_ONLY(NodeParametersInterface)
  using OnSetParametersCallbackType =
    OnSetParametersCallbackHandle::OnSetParametersCallbackType;
  using PreSetParametersCallbackType =
    PreSetParametersCallbackHandle::PreSetParametersCallbackType;
  using PostSetParametersCallbackType =
    PostSetParametersCallbackHandle::PostSetParametersCallbackType;
  virtual ~NodeParametersInterface();
  virtual const std::map<std::string, rclcpp::ParameterValue> &
  get_parameter_overrides() const = 0;
  virtual const ParameterValue & declare_parameter(
    const std::string & name, const ParameterValue & default_value,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false) = 0;
  virtual const ParameterValue & declare_parameter(
    const std::string & name, ParameterType type,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false) = 0;
  virtual void undeclare_parameter(const std::string & name) = 0;
  virtual bool has_parameter(const std::string & name) const = 0;
  virtual std::vector<rcl_interfaces::msg::SetParametersResult> set_parameters(
    const std::vector<Parameter> & parameters) = 0;
  virtual rcl_interfaces::msg::SetParametersResult set_parameters_atomically(
    const std::vector<Parameter> & parameters) = 0;
  virtual std::vector<Parameter> get_parameters(
    const std::vector<std::string> & names) const = 0;
  virtual Parameter get_parameter(const std::string & name) const = 0;
  virtual bool get_parameter(const std::string & name, Parameter & parameter) const = 0;
  virtual bool get_parameters_by_prefix(
    const std::string & prefix, std::map<std::string, Parameter> & parameters) const = 0;
  virtual std::vector<rcl_interfaces::msg::ParameterDescriptor> describe_parameters(
    const std::vector<std::string> & names) const = 0;
  virtual std::vector<uint8_t> get_parameter_types(
    const std::vector<std::string> & names) const = 0;
  virtual OnSetParametersCallbackHandle::SharedPtr add_on_set_parameters_callback(
    OnSetParametersCallbackType callback) = 0;
  virtual void remove_on_set_parameters_callback(
    const OnSetParametersCallbackHandle * const handler) = 0;
  virtual PreSetParametersCallbackHandle::SharedPtr add_pre_set_parameters_callback(
    PreSetParametersCallbackType callback) = 0;
  virtual PostSetParametersCallbackHandle::SharedPtr add_post_set_parameters_callback(
    PostSetParametersCallbackType callback) = 0;
};

// get_node_*_interface(node): node, pointer or shared_ptr to a node
template<class NodeT>
NodeBaseInterface::SharedPtr get_node_base_interface(NodeT && node);
template<class NodeT>
NodeClockInterface::SharedPtr get_node_clock_interface(NodeT && node);
template<class NodeT>
NodeTimersInterface::SharedPtr get_node_timers_interface(NodeT && node);
template<class NodeT>
NodeTopicsInterface::SharedPtr get_node_topics_interface(NodeT && node);
template<class NodeT>
NodeParametersInterface::SharedPtr get_node_parameters_interface(
  NodeT && node);
}  // namespace node_interfaces

// node.hpp
// what the graph knows of a topic's publishers and subscriptions
enum class EndpointType
{
  Invalid = 0,
  Publisher,
  Subscription
};

class TopicEndpointInfo
{
public:
  std::string & node_name();
  const std::string & node_name() const;
  std::string & node_namespace();
  const std::string & node_namespace() const;
  std::string & topic_type();
  const std::string & topic_type() const;
  EndpointType & endpoint_type();
  const EndpointType & endpoint_type() const;
  rclcpp::QoS & qos_profile();
  const rclcpp::QoS & qos_profile() const;
};

class Node : public std::enable_shared_from_this<Node>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Node)

  using OnSetParametersCallbackHandle =
    node_interfaces::OnSetParametersCallbackHandle;
  using OnSetParametersCallbackType =
    node_interfaces::NodeParametersInterface::OnSetParametersCallbackType;
  using OnParametersSetCallbackType = OnSetParametersCallbackType;
  using PreSetParametersCallbackHandle =
    node_interfaces::PreSetParametersCallbackHandle;
  using PreSetParametersCallbackType =
    node_interfaces::NodeParametersInterface::PreSetParametersCallbackType;
  using PostSetParametersCallbackHandle =
    node_interfaces::PostSetParametersCallbackHandle;
  using PostSetParametersCallbackType =
    node_interfaces::NodeParametersInterface::PostSetParametersCallbackType;

  explicit Node(const std::string & node_name,
                const NodeOptions & options = NodeOptions());
  explicit Node(const std::string & node_name, const std::string & namespace_,
                const NodeOptions & options = NodeOptions());
  virtual ~Node();

  const char * get_name() const;
  const char * get_namespace() const;
  const char * get_fully_qualified_name() const;
  Logger get_logger() const;
  CallbackGroup::SharedPtr create_callback_group(
    CallbackGroupType group_type,
    bool automatically_add_to_executor_with_node = true);

  template<class MessageT, class AllocatorT = std::allocator<void>,
    class PublisherT = Publisher<MessageT, AllocatorT>>
  std::shared_ptr<PublisherT> create_publisher(
    const std::string & topic_name, const QoS & qos,
    const PublisherOptionsWithAllocator<AllocatorT> & options =
    PublisherOptionsWithAllocator<AllocatorT>());

  template<class MessageT, class CallbackT,
    class AllocatorT = std::allocator<void>,
    class SubscriptionT = Subscription<MessageT, AllocatorT>>
  std::shared_ptr<SubscriptionT> create_subscription(
    const std::string & topic_name, const QoS & qos, CallbackT && callback,
    const SubscriptionOptionsWithAllocator<AllocatorT> & options =
    SubscriptionOptionsWithAllocator<AllocatorT>());

  // `autostart` from Jazzy on
  template<class DurationRepT = int64_t, class DurationT = std::milli,
    class CallbackT>
  typename WallTimer<CallbackT>::SharedPtr create_wall_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    CallbackGroup::SharedPtr group = nullptr, bool autostart = true);

  // Jazzy+: a timer on the node's clock (ROS time)
  template<class DurationRepT = int64_t, class DurationT = std::milli,
    class CallbackT>
  typename GenericTimer<CallbackT>::SharedPtr create_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    CallbackGroup::SharedPtr group = nullptr);

  // the rmw_qos_profile_t forms: Humble, deprecated in Jazzy
  template<class ServiceT>
  typename Client<ServiceT>::SharedPtr create_client(
    const std::string & service_name, const rmw_qos_profile_t & qos_profile,
    CallbackGroup::SharedPtr group = nullptr);
  template<class ServiceT>
  typename Client<ServiceT>::SharedPtr create_client(
    const std::string & service_name, const QoS & qos = ServicesQoS(),
    CallbackGroup::SharedPtr group = nullptr);

  template<class ServiceT, class CallbackT>
  typename Service<ServiceT>::SharedPtr create_service(
    const std::string & service_name, CallbackT && callback,
    const rmw_qos_profile_t & qos_profile,
    CallbackGroup::SharedPtr group = nullptr);
  template<class ServiceT, class CallbackT>
  typename Service<ServiceT>::SharedPtr create_service(
    const std::string & service_name, CallbackT && callback,
    const QoS & qos = ServicesQoS(), CallbackGroup::SharedPtr group = nullptr);

  template<class AllocatorT = std::allocator<void>>
  std::shared_ptr<GenericPublisher> create_generic_publisher(
    const std::string & topic_name, const std::string & topic_type,
    const QoS & qos,
    const PublisherOptionsWithAllocator<AllocatorT> & options =
    PublisherOptionsWithAllocator<AllocatorT>());

  // Humble takes std::function<void(std::shared_ptr<SerializedMessage>)>,
  // later distros any callable: the template accepts both
  template<class CallbackT, class AllocatorT = std::allocator<void>>
  std::shared_ptr<GenericSubscription> create_generic_subscription(
    const std::string & topic_name, const std::string & topic_type,
    const QoS & qos, CallbackT && callback,
    const SubscriptionOptionsWithAllocator<AllocatorT> & options =
    SubscriptionOptionsWithAllocator<AllocatorT>());

  // Jazzy+
  typename GenericClient::SharedPtr create_generic_client(
    const std::string & service_name, const std::string & service_type,
    const QoS & qos = ServicesQoS(), CallbackGroup::SharedPtr group = nullptr);

  const ParameterValue & declare_parameter(
    const std::string & name, const ParameterValue & default_value,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false);
  const ParameterValue & declare_parameter(
    const std::string & name, ParameterType type,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor{},
    bool ignore_override = false);
  template<class ParameterT>
  auto declare_parameter(
    const std::string & name, const ParameterT & default_value,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false)
  -> typename std::conditional<
    std::is_array<ParameterT>::value, std::string, ParameterT>::type;
  template<class ParameterT>
  auto declare_parameter(
    const std::string & name,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false) -> ParameterT;
  template<class ParameterT>
  std::vector<ParameterT> declare_parameters(
    const std::string & namespace_,
    const std::map<std::string, ParameterT> & parameters,
    bool ignore_overrides = false);
  void undeclare_parameter(const std::string & name);
  bool has_parameter(const std::string & name) const;
  rcl_interfaces::msg::SetParametersResult set_parameter(
    const Parameter & parameter);
  std::vector<rcl_interfaces::msg::SetParametersResult> set_parameters(
    const std::vector<Parameter> & parameters);
  rcl_interfaces::msg::SetParametersResult set_parameters_atomically(
    const std::vector<Parameter> & parameters);
  Parameter get_parameter(const std::string & name) const;
  bool get_parameter(const std::string & name, Parameter & parameter) const;
  template<class ParameterT>
  bool get_parameter(const std::string & name, ParameterT & parameter) const;
  template<class ParameterT>
  bool get_parameter_or(const std::string & name, ParameterT & parameter,
                        const ParameterT & alternative_value) const;
  template<class ParameterT>
  ParameterT get_parameter_or(const std::string & name,
                              const ParameterT & alternative_value) const;
  std::vector<Parameter> get_parameters(
    const std::vector<std::string> & names) const;
  template<class ParameterT>
  bool get_parameters(const std::string & prefix,
                      std::map<std::string, ParameterT> & values) const;

  // Jazzy+: pre/post; all: on_set
  RCUTILS_WARN_UNUSED
  PreSetParametersCallbackHandle::SharedPtr add_pre_set_parameters_callback(
    PreSetParametersCallbackType callback);
  RCUTILS_WARN_UNUSED
  OnSetParametersCallbackHandle::SharedPtr add_on_set_parameters_callback(
    OnSetParametersCallbackType callback);
  RCUTILS_WARN_UNUSED
  PostSetParametersCallbackHandle::SharedPtr add_post_set_parameters_callback(
    PostSetParametersCallbackType callback);
  void remove_on_set_parameters_callback(
    const OnSetParametersCallbackHandle * const handler);

  std::vector<std::string> get_node_names() const;
  std::map<std::string, std::vector<std::string>>
  get_topic_names_and_types() const;
  std::map<std::string, std::vector<std::string>>
  get_service_names_and_types() const;
  std::size_t count_publishers(const std::string & topic_name) const;
  std::size_t count_subscribers(const std::string & topic_name) const;
  std::vector<TopicEndpointInfo> get_publishers_info_by_topic(
    const std::string & topic_name, bool no_mangle = false) const;
  std::vector<TopicEndpointInfo> get_subscriptions_info_by_topic(
    const std::string & topic_name, bool no_mangle = false) const;
  rcl_interfaces::msg::ListParametersResult list_parameters(
    const std::vector<std::string> & prefixes, uint64_t depth) const;
  Event::SharedPtr get_graph_event();
  void wait_for_graph_change(Event::SharedPtr event,
                             std::chrono::nanoseconds timeout);

  Clock::SharedPtr get_clock();
  Clock::ConstSharedPtr get_clock() const;
  Time now() const;

  node_interfaces::NodeBaseInterface::SharedPtr get_node_base_interface();
  node_interfaces::NodeClockInterface::SharedPtr get_node_clock_interface();
  node_interfaces::NodeGraphInterface::SharedPtr get_node_graph_interface();
  node_interfaces::NodeLoggingInterface::SharedPtr
  get_node_logging_interface();
  node_interfaces::NodeTimersInterface::SharedPtr get_node_timers_interface();
  node_interfaces::NodeTopicsInterface::SharedPtr get_node_topics_interface();
  node_interfaces::NodeServicesInterface::SharedPtr
  get_node_services_interface();
  node_interfaces::NodeWaitablesInterface::SharedPtr
  get_node_waitables_interface();
  node_interfaces::NodeParametersInterface::SharedPtr
  get_node_parameters_interface();
  node_interfaces::NodeTimeSourceInterface::SharedPtr
  get_node_time_source_interface();

  // relative names of entities made through the sub-node get
  // `<namespace>/<sub_namespace>/`
  const std::string & get_sub_namespace() const;
  const std::string & get_effective_namespace() const;
  Node::SharedPtr create_sub_node(const std::string & sub_namespace);
  const NodeOptions & get_node_options() const;

protected:
  Node(const Node & other, const std::string & sub_namespace);
};

// free functions: create_publisher.hpp
template<class MessageT, class AllocatorT = std::allocator<void>,
  class PublisherT = Publisher<MessageT, AllocatorT>, class NodeT>
std::shared_ptr<PublisherT> create_publisher(
  NodeT && node, const std::string & topic_name, const QoS & qos,
  const PublisherOptionsWithAllocator<AllocatorT> & options =
  PublisherOptionsWithAllocator<AllocatorT>());

template<class MessageT, class AllocatorT = std::allocator<void>,
  class PublisherT = Publisher<MessageT, AllocatorT>>
std::shared_ptr<PublisherT> create_publisher(
  node_interfaces::NodeParametersInterface::SharedPtr & node_parameters,
  node_interfaces::NodeTopicsInterface::SharedPtr & node_topics,
  const std::string & topic_name, const QoS & qos,
  const PublisherOptionsWithAllocator<AllocatorT> & options =
  PublisherOptionsWithAllocator<AllocatorT>());

// create_subscription.hpp (the node is taken by non-const reference)
template<class MessageT, class CallbackT,
  class AllocatorT = std::allocator<void>,
  class SubscriptionT = Subscription<MessageT, AllocatorT>, class NodeT>
std::shared_ptr<SubscriptionT> create_subscription(
  NodeT & node, const std::string & topic_name, const QoS & qos,
  CallbackT && callback,
  const SubscriptionOptionsWithAllocator<AllocatorT> & options =
  SubscriptionOptionsWithAllocator<AllocatorT>());

template<class MessageT, class CallbackT,
  class AllocatorT = std::allocator<void>,
  class SubscriptionT = Subscription<MessageT, AllocatorT>>
std::shared_ptr<SubscriptionT> create_subscription(
  node_interfaces::NodeParametersInterface::SharedPtr & node_parameters,
  node_interfaces::NodeTopicsInterface::SharedPtr & node_topics,
  const std::string & topic_name, const QoS & qos, CallbackT && callback,
  const SubscriptionOptionsWithAllocator<AllocatorT> & options =
  SubscriptionOptionsWithAllocator<AllocatorT>());

// create_timer.hpp (`autostart` from Jazzy on)
template<class CallbackT>
TimerBase::SharedPtr create_timer(
  std::shared_ptr<node_interfaces::NodeBaseInterface> node_base,
  std::shared_ptr<node_interfaces::NodeTimersInterface> node_timers,
  Clock::SharedPtr clock, Duration period, CallbackT && callback,
  CallbackGroup::SharedPtr group = nullptr, bool autostart = true);

template<class NodeT, class CallbackT>
TimerBase::SharedPtr create_timer(
  NodeT node, Clock::SharedPtr clock, Duration period, CallbackT && callback,
  CallbackGroup::SharedPtr group = nullptr, bool autostart = true);

// Jazzy+
template<class DurationRepT, class DurationT, class CallbackT>
typename GenericTimer<CallbackT>::SharedPtr create_timer(
  Clock::SharedPtr clock,
  std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
  CallbackGroup::SharedPtr group, node_interfaces::NodeBaseInterface * node_base,
  node_interfaces::NodeTimersInterface * node_timers, bool autostart = true);

template<class DurationRepT, class DurationT, class CallbackT>
typename WallTimer<CallbackT>::SharedPtr create_wall_timer(
  std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
  CallbackGroup::SharedPtr group, node_interfaces::NodeBaseInterface * node_base,
  node_interfaces::NodeTimersInterface * node_timers, bool autostart = true);

// create_service.hpp, create_client.hpp
template<class ServiceT, class CallbackT>
typename Service<ServiceT>::SharedPtr create_service(
  std::shared_ptr<node_interfaces::NodeBaseInterface> node_base,
  std::shared_ptr<node_interfaces::NodeServicesInterface> node_services,
  const std::string & service_name, CallbackT && callback,
  const QoS & qos, CallbackGroup::SharedPtr group);

template<class ServiceT>
typename Client<ServiceT>::SharedPtr create_client(
  std::shared_ptr<node_interfaces::NodeBaseInterface> node_base,
  std::shared_ptr<node_interfaces::NodeGraphInterface> node_graph,
  std::shared_ptr<node_interfaces::NodeServicesInterface> node_services,
  const std::string & service_name, const QoS & qos = ServicesQoS(),
  CallbackGroup::SharedPtr group = nullptr);

// create_generic_publisher.hpp, create_generic_subscription.hpp
template<class AllocatorT = std::allocator<void>>
std::shared_ptr<GenericPublisher> create_generic_publisher(
  node_interfaces::NodeTopicsInterface::SharedPtr topics_interface,
  const std::string & topic_name, const std::string & topic_type,
  const QoS & qos,
  const PublisherOptionsWithAllocator<AllocatorT> & options =
  PublisherOptionsWithAllocator<AllocatorT>());

template<class CallbackT, class AllocatorT = std::allocator<void>>
std::shared_ptr<GenericSubscription> create_generic_subscription(
  node_interfaces::NodeTopicsInterface::SharedPtr topics_interface,
  const std::string & topic_name, const std::string & topic_type,
  const QoS & qos, CallbackT && callback,
  const SubscriptionOptionsWithAllocator<AllocatorT> & options =
  SubscriptionOptionsWithAllocator<AllocatorT>());

// rate.hpp: the Jazzy+ classes (Humble: `using Rate = GenericRate<
// std::chrono::system_clock>; using WallRate = GenericRate<steady_clock>`;
// user code of both reads alike)
class RateBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(RateBase)
  virtual ~RateBase();
  virtual bool sleep() = 0;
  virtual rcl_clock_type_t get_type() const = 0;
  virtual void reset() = 0;
};

// Humble; deprecated in Jazzy, gone in Rolling
template<class Clock = std::chrono::high_resolution_clock>
class GenericRate : public RateBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericRate)
  explicit GenericRate(double rate);
  explicit GenericRate(std::chrono::nanoseconds period);
  virtual bool sleep();
  virtual bool is_steady() const;
  virtual rcl_clock_type_t get_type() const;
  virtual void reset();
  std::chrono::nanoseconds period() const;
};

class Rate : public RateBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Rate)
  explicit Rate(const double rate,
                Clock::SharedPtr clock = std::make_shared<Clock>(RCL_SYSTEM_TIME));
  explicit Rate(const Duration & period,
                Clock::SharedPtr clock = std::make_shared<Clock>(RCL_SYSTEM_TIME));
  // a field or a value of a library the model lacks (`Rate(params.rate)`):
  // a rate in hertz, which it holds far more often than a duration message;
  // with the two constructors above alone, it would tie between them
  template<class A, typename std::enable_if<
      rsia_model::IsField<A>::value, int>::type = 0>
  explicit Rate(const A & rate,
                Clock::SharedPtr clock = std::make_shared<Clock>(RCL_SYSTEM_TIME));
  virtual bool sleep();
  virtual bool is_steady() const;
  virtual rcl_clock_type_t get_type() const;
  virtual void reset();
  std::chrono::nanoseconds period() const;
};

class WallRate : public Rate
{
public:
  explicit WallRate(const double rate);
  explicit WallRate(const Duration & period);
  // a rate in hertz, as Rate's
  template<class A, typename std::enable_if<
      rsia_model::IsField<A>::value, int>::type = 0>
  explicit WallRate(const A & rate);
};

// Rolling
class ROSRate : public Rate
{
public:
  explicit ROSRate(const double rate);
  explicit ROSRate(const Duration & period);
};

// executors
class ExecutorOptions
{
public:
  ExecutorOptions();
};

class Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS_NOT_COPYABLE(Executor)
  explicit Executor(const ExecutorOptions & options = ExecutorOptions());
  virtual ~Executor();
  virtual void spin() = 0;
  virtual void add_node(
    node_interfaces::NodeBaseInterface::SharedPtr node_ptr, bool notify = true);
  virtual void add_node(Node::SharedPtr node_ptr, bool notify = true);
  virtual void remove_node(
    node_interfaces::NodeBaseInterface::SharedPtr node_ptr, bool notify = true);
  virtual void remove_node(Node::SharedPtr node_ptr, bool notify = true);
  virtual void add_callback_group(
    CallbackGroup::SharedPtr group_ptr,
    node_interfaces::NodeBaseInterface::SharedPtr node_ptr, bool notify = true);
  void spin_node_once(Node::SharedPtr node,
                      std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1));
  void spin_node_some(Node::SharedPtr node);
  virtual void spin_some(
    std::chrono::nanoseconds max_duration = std::chrono::nanoseconds(0));
  virtual void spin_all(std::chrono::nanoseconds max_duration);
  virtual void spin_once(
    std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1));
  template<class FutureT, class TimeRepT = int64_t, class TimeT = std::milli>
  FutureReturnCode spin_until_future_complete(
    const FutureT & future,
    std::chrono::duration<TimeRepT, TimeT> timeout =
    std::chrono::duration<TimeRepT, TimeT>(-1));
  void cancel();
};

namespace executors
{
class SingleThreadedExecutor : public Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(SingleThreadedExecutor)
  explicit SingleThreadedExecutor(
    const ExecutorOptions & options = ExecutorOptions());
  void spin() override;
};
class MultiThreadedExecutor : public Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(MultiThreadedExecutor)
  explicit MultiThreadedExecutor(
    const ExecutorOptions & options = ExecutorOptions(),
    std::size_t number_of_threads = 0, bool yield_before_execute = false,
    std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1));
  void spin() override;
  std::size_t get_number_of_threads();
};
class StaticSingleThreadedExecutor : public Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(StaticSingleThreadedExecutor)
  explicit StaticSingleThreadedExecutor(
    const ExecutorOptions & options = ExecutorOptions());
  void spin() override;
};
}  // namespace executors

namespace experimental
{
namespace executors
{
class EventsExecutor : public rclcpp::Executor
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(EventsExecutor)
  explicit EventsExecutor(
    const rclcpp::ExecutorOptions & options = rclcpp::ExecutorOptions());
  void spin() override;
};
}  // namespace executors
}  // namespace experimental

void spin(node_interfaces::NodeBaseInterface::SharedPtr node_ptr);
void spin(Node::SharedPtr node_ptr);
void spin_some(node_interfaces::NodeBaseInterface::SharedPtr node_ptr);
void spin_some(Node::SharedPtr node_ptr);
template<class FutureT, class TimeRepT = int64_t, class TimeT = std::milli>
FutureReturnCode spin_until_future_complete(
  Node::SharedPtr node_ptr, const FutureT & future,
  std::chrono::duration<TimeRepT, TimeT> timeout =
  std::chrono::duration<TimeRepT, TimeT>(-1));
template<class FutureT, class TimeRepT = int64_t, class TimeT = std::milli>
FutureReturnCode spin_until_future_complete(
  node_interfaces::NodeBaseInterface::SharedPtr node_ptr,
  const FutureT & future,
  std::chrono::duration<TimeRepT, TimeT> timeout =
  std::chrono::duration<TimeRepT, TimeT>(-1));

// parameter_event_handler.hpp: a subscription to /parameter_events that
// the user's code makes, with callbacks per parameter or per event
struct ParameterCallbackHandle
{
  using SharedPtr = std::shared_ptr<ParameterCallbackHandle>;
  using ParameterCallbackType = std::function<void (const Parameter &)>;
};
struct ParameterEventCallbackHandle
{
  using SharedPtr = std::shared_ptr<ParameterEventCallbackHandle>;
  using ParameterEventCallbackType =
    std::function<void (const rcl_interfaces::msg::ParameterEvent &)>;
};
class ParameterEventHandler
{
public:
  template<typename NodeT>
  explicit ParameterEventHandler(NodeT node, const QoS & qos = QoS(1000));
  ParameterEventCallbackHandle::SharedPtr add_parameter_event_callback(
    ParameterEventCallbackHandle::ParameterEventCallbackType callback);
  void remove_parameter_event_callback(
    ParameterEventCallbackHandle::SharedPtr callback_handle);
  ParameterCallbackHandle::SharedPtr add_parameter_callback(
    const std::string & parameter_name,
    ParameterCallbackHandle::ParameterCallbackType callback,
    const std::string & node_name = "");
  void remove_parameter_callback(
    ParameterCallbackHandle::SharedPtr callback_handle);
  static bool get_parameter_from_event(
    const rcl_interfaces::msg::ParameterEvent & event,
    Parameter & parameter, const std::string & parameter_name,
    const std::string & node_name = "");
  static Parameter get_parameter_from_event(
    const rcl_interfaces::msg::ParameterEvent & event,
    const std::string & parameter_name, const std::string & node_name = "");
  static std::vector<Parameter> get_parameters_from_event(
    const rcl_interfaces::msg::ParameterEvent & event);
};

// wait_for_message.hpp: one message from an existing subscription, or
// from a temporary one on `topic` (node form; Rolling adds the
// node-interfaces form)
template<class MsgT, class Rep = int64_t, class Period = std::milli>
bool wait_for_message(
  MsgT & out, std::shared_ptr<Subscription<MsgT>> subscription,
  std::shared_ptr<Context> context,
  std::chrono::duration<Rep, Period> time_to_wait =
  std::chrono::duration<Rep, Period>(-1));
template<class MsgT, class Rep = int64_t, class Period = std::milli>
bool wait_for_message(
  MsgT & out,
  node_interfaces::NodeParametersInterface::SharedPtr node_parameters,
  node_interfaces::NodeTopicsInterface::SharedPtr node_topics,
  const std::string & topic,
  std::chrono::duration<Rep, Period> time_to_wait =
  std::chrono::duration<Rep, Period>(-1),
  const QoS & qos = SystemDefaultsQoS());
template<class MsgT, class Rep = int64_t, class Period = std::milli>
bool wait_for_message(
  MsgT & out, Node::SharedPtr node, const std::string & topic,
  std::chrono::duration<Rep, Period> time_to_wait =
  std::chrono::duration<Rep, Period>(-1),
  const QoS & qos = SystemDefaultsQoS());

// parameter_client.hpp: clients of another node's parameter services
// both clients' on_parameter_event: the subscription to /parameter_events
// (rclcpp creates it on the node the client was made with)
#define RSIA_MODEL_ON_PARAMETER_EVENT_                                                      \
  template<class CallbackT, class AllocatorT = std::allocator<void>>                        \
  typename Subscription<rcl_interfaces::msg::ParameterEvent, AllocatorT>::SharedPtr         \
  on_parameter_event(                                                                       \
    CallbackT && callback, const QoS & qos = ParameterEventsQoS(),                          \
    const SubscriptionOptionsWithAllocator<AllocatorT> & options =                          \
    SubscriptionOptionsWithAllocator<AllocatorT>());                                        \
  template<class CallbackT, class NodeT, class AllocatorT = std::allocator<void>>           \
  static typename Subscription<rcl_interfaces::msg::ParameterEvent, AllocatorT>::SharedPtr  \
  on_parameter_event(                                                                       \
    NodeT && node, CallbackT && callback, const QoS & qos = ParameterEventsQoS(),           \
    const SubscriptionOptionsWithAllocator<AllocatorT> & options =                          \
    SubscriptionOptionsWithAllocator<AllocatorT>());

class AsyncParametersClient
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(AsyncParametersClient)
  template<class NodeT>
  explicit AsyncParametersClient(
    NodeT node, const std::string & remote_node_name = "",
    const QoS & qos_profile = ParametersQoS(),
    CallbackGroup::SharedPtr group = nullptr);
  bool service_is_ready() const;
  template<class RepT = int64_t, class RatioT = std::milli>
  bool wait_for_service(
    std::chrono::duration<RepT, RatioT> timeout =
    std::chrono::duration<RepT, RatioT>(-1));
  template<class... RsiaArgs>
  std::shared_future<std::vector<rclcpp::Parameter>> get_parameters(
    const std::vector<std::string> & names, RsiaArgs &&...);
  template<class... RsiaArgs>
  std::shared_future<std::vector<rcl_interfaces::msg::SetParametersResult>>
  set_parameters(const std::vector<rclcpp::Parameter> & parameters,
    RsiaArgs &&...);
  template<class... RsiaArgs>
  std::shared_future<rcl_interfaces::msg::SetParametersResult>
  set_parameters_atomically(
    const std::vector<rclcpp::Parameter> & parameters, RsiaArgs &&...);
  RSIA_MODEL_ON_PARAMETER_EVENT_
};

class SyncParametersClient
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(SyncParametersClient)
  template<class NodeT>
  explicit SyncParametersClient(
    NodeT node, const std::string & remote_node_name = "",
    const QoS & qos_profile = ParametersQoS());
  template<class ExecutorT, class NodeT>
  SyncParametersClient(
    ExecutorT executor, NodeT node, const std::string & remote_node_name = "",
    const QoS & qos_profile = ParametersQoS());
  bool service_is_ready() const;
  template<class RepT = int64_t, class RatioT = std::milli>
  bool wait_for_service(
    std::chrono::duration<RepT, RatioT> timeout =
    std::chrono::duration<RepT, RatioT>(-1));
  template<class... RsiaArgs>
  std::vector<rclcpp::Parameter> get_parameters(
    const std::vector<std::string> & parameter_names, RsiaArgs &&...);
  template<class T>
  T get_parameter(const std::string & parameter_name, const T & default_value);
  bool has_parameter(const std::string & parameter_name);
  template<class... RsiaArgs>
  std::vector<rcl_interfaces::msg::SetParametersResult> set_parameters(
    const std::vector<rclcpp::Parameter> & parameters, RsiaArgs &&...);
  RSIA_MODEL_ON_PARAMETER_EVENT_
};
#undef RSIA_MODEL_ON_PARAMETER_EVENT_

// expand_topic_or_service_name.hpp
std::string expand_topic_or_service_name(
  const std::string & name, const std::string & node_name,
  const std::string & namespace_, bool is_service = false);

}  // namespace rclcpp

// logging macros: the arguments stay expressions in a do/while(0) like the
// real expansion; the _ONCE/_THROTTLE/_SKIPFIRST/_EXPRESSION/_FUNCTION
// variants keep their extra leading arguments
void rsia_model_rclcpp_log(...);
#define RSIA_MODEL_RCLCPP_LOG(...) \
  do { rsia_model_rclcpp_log(__VA_ARGS__); } while (0)

#define RCUTILS_LOG_DEBUG(...) RSIA_MODEL_RCLCPP_LOG(__VA_ARGS__)
#define RCUTILS_LOG_INFO(...) RSIA_MODEL_RCLCPP_LOG(__VA_ARGS__)
#define RCUTILS_LOG_WARN(...) RSIA_MODEL_RCLCPP_LOG(__VA_ARGS__)
#define RCUTILS_LOG_ERROR(...) RSIA_MODEL_RCLCPP_LOG(__VA_ARGS__)
#define RCUTILS_LOG_FATAL(...) RSIA_MODEL_RCLCPP_LOG(__VA_ARGS__)
#define RCUTILS_LOG_DEBUG_NAMED(name, ...) RSIA_MODEL_RCLCPP_LOG(name, __VA_ARGS__)
#define RCUTILS_LOG_INFO_NAMED(name, ...) RSIA_MODEL_RCLCPP_LOG(name, __VA_ARGS__)
#define RCUTILS_LOG_WARN_NAMED(name, ...) RSIA_MODEL_RCLCPP_LOG(name, __VA_ARGS__)
#define RCUTILS_LOG_ERROR_NAMED(name, ...) RSIA_MODEL_RCLCPP_LOG(name, __VA_ARGS__)
#define RCUTILS_LOG_FATAL_NAMED(name, ...) RSIA_MODEL_RCLCPP_LOG(name, __VA_ARGS__)
#define RCLCPP_DEBUG(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_ONCE(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_ONCE(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN_ONCE(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR_ONCE(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL_ONCE(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_SKIPFIRST(logger, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_SKIPFIRST(logger, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN_SKIPFIRST(logger, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR_SKIPFIRST(logger, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_DEBUG_EXPRESSION(logger, expression, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, expression, __VA_ARGS__)
#define RCLCPP_INFO_EXPRESSION(logger, expression, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, expression, __VA_ARGS__)
#define RCLCPP_WARN_EXPRESSION(logger, expression, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, expression, __VA_ARGS__)
#define RCLCPP_ERROR_EXPRESSION(logger, expression, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, expression, __VA_ARGS__)
#define RCLCPP_DEBUG_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_INFO_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_WARN_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_ERROR_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_FATAL_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
// the _STREAM forms build the text with an ostream
#define RSIA_MODEL_RCLCPP_STREAM(logger, stream) \
  do { std::stringstream rclcpp_stream_ss_; rclcpp_stream_ss_ << stream; \
    rsia_model_rclcpp_log(logger, rclcpp_stream_ss_.str().c_str()); } while (0)
#define RCLCPP_DEBUG_STREAM(logger, stream) RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_INFO_STREAM(logger, stream) RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_WARN_STREAM(logger, stream) RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_ERROR_STREAM(logger, stream) RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_FATAL_STREAM(logger, stream) RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_INFO_STREAM_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_WARN_STREAM_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)

// the other forms of rclcpp/logging.hpp, for each severity (the model
// evaluates the arguments; the conditions, once and throttle are
// the log's, not the node's rate)
#define RCLCPP_DEBUG_FUNCTION(logger, function, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, function, __VA_ARGS__)
#define RCLCPP_DEBUG_SKIPFIRST_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_DEBUG_STREAM_ONCE(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_DEBUG_STREAM_EXPRESSION(logger, expression, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_DEBUG_STREAM_FUNCTION(logger, function, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_DEBUG_STREAM_SKIPFIRST(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_DEBUG_STREAM_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_DEBUG_STREAM_SKIPFIRST_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_INFO_FUNCTION(logger, function, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, function, __VA_ARGS__)
#define RCLCPP_INFO_SKIPFIRST_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_INFO_STREAM_ONCE(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_INFO_STREAM_EXPRESSION(logger, expression, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_INFO_STREAM_FUNCTION(logger, function, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_INFO_STREAM_SKIPFIRST(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_INFO_STREAM_SKIPFIRST_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_WARN_FUNCTION(logger, function, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, function, __VA_ARGS__)
#define RCLCPP_WARN_SKIPFIRST_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_WARN_STREAM_ONCE(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_WARN_STREAM_EXPRESSION(logger, expression, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_WARN_STREAM_FUNCTION(logger, function, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_WARN_STREAM_SKIPFIRST(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_WARN_STREAM_SKIPFIRST_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_ERROR_FUNCTION(logger, function, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, function, __VA_ARGS__)
#define RCLCPP_ERROR_SKIPFIRST_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_ERROR_STREAM_ONCE(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_ERROR_STREAM_EXPRESSION(logger, expression, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_ERROR_STREAM_FUNCTION(logger, function, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_ERROR_STREAM_SKIPFIRST(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_ERROR_STREAM_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_ERROR_STREAM_SKIPFIRST_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_FATAL_EXPRESSION(logger, expression, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, expression, __VA_ARGS__)
#define RCLCPP_FATAL_FUNCTION(logger, function, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, function, __VA_ARGS__)
#define RCLCPP_FATAL_SKIPFIRST(logger, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL_SKIPFIRST_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_FATAL_STREAM_ONCE(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_FATAL_STREAM_EXPRESSION(logger, expression, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_FATAL_STREAM_FUNCTION(logger, function, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_FATAL_STREAM_SKIPFIRST(logger, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_FATAL_STREAM_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)
#define RCLCPP_FATAL_STREAM_SKIPFIRST_THROTTLE(logger, clock, ms, stream) \
  RSIA_MODEL_RCLCPP_STREAM(logger, stream)

#endif  // RSIA_MODEL_RCLCPP_RCLCPP_HPP
