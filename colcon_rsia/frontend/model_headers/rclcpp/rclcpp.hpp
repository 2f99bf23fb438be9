// colcon-rsia model of <rclcpp/rclcpp.hpp> (ROS 2, Humble/Jazzy/Rolling):
// declarations of the rclcpp API the analysis recognises, written from the
// documented signatures (shared/reference/ros-api.md section 2). Every other
// rclcpp header of the model includes this one. RSIA_MODEL_RCLCPP tells the
// headers ROS 1 and ROS 2 share (tf2_ros/*.h) which API to declare.
#ifndef RSIA_MODEL_RCLCPP_RCLCPP_HPP
#define RSIA_MODEL_RCLCPP_RCLCPP_HPP
#define RSIA_MODEL_RCLCPP 1

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#define RCLCPP_SMART_PTR_DEFINITIONS(...) \
  using SharedPtr = std::shared_ptr<__VA_ARGS__>; \
  using ConstSharedPtr = std::shared_ptr<const __VA_ARGS__>; \
  using UniquePtr = std::unique_ptr<__VA_ARGS__>; \
  using WeakPtr = std::weak_ptr<__VA_ARGS__>;

struct rmw_request_id_t
{
  int64_t sequence_number;
};

struct rmw_qos_profile_t
{
  std::size_t depth;
};
extern const rmw_qos_profile_t rmw_qos_profile_default;
extern const rmw_qos_profile_t rmw_qos_profile_services_default;
extern const rmw_qos_profile_t rmw_qos_profile_sensor_data;

namespace rclcpp
{

class Context
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Context)
};

void init(int argc, char const * const * argv);
bool shutdown();
bool ok();
bool sleep_for(const std::chrono::nanoseconds & nanoseconds,
               Context::SharedPtr context = nullptr);

class Logger
{
public:
  Logger get_child(const std::string & suffix);
  const char * get_name() const;
};
Logger get_logger(const std::string & name);

class Duration
{
public:
  Duration(int32_t seconds, uint32_t nanoseconds);
  template<class Rep, class Period>
  Duration(const std::chrono::duration<Rep, Period> & duration);
  static Duration from_seconds(double seconds);
  static Duration from_nanoseconds(int64_t nanoseconds);
  double seconds() const;
  int64_t nanoseconds() const;
  Duration operator+(const Duration & rhs) const;
  Duration operator-(const Duration & rhs) const;
  bool operator<(const Duration & rhs) const;
  bool operator>(const Duration & rhs) const;
};

class Time
{
public:
  Time();
  Time(int32_t seconds, uint32_t nanoseconds);
  double seconds() const;
  int64_t nanoseconds() const;
  Duration operator-(const Time & rhs) const;
  Time operator+(const Duration & rhs) const;
  bool operator<(const Time & rhs) const;
  bool operator>(const Time & rhs) const;
  template<class M>
  operator M() const;
};

class Clock
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Clock)
  Clock();
  Time now();
  bool sleep_for(Duration rel_time, Context::SharedPtr context = nullptr);
};

class QoS
{
public:
  QoS(std::size_t history_depth);
  QoS & keep_last(std::size_t depth);
  QoS & keep_all();
  QoS & reliable();
  QoS & best_effort();
  QoS & durability_volatile();
  QoS & transient_local();
  const rmw_qos_profile_t & get_rmw_qos_profile() const;
};

class KeepLast
{
public:
  explicit KeepLast(std::size_t depth);
};

class SensorDataQoS : public QoS
{
public:
  SensorDataQoS();
};

class SystemDefaultsQoS : public QoS
{
public:
  SystemDefaultsQoS();
};

class ServicesQoS : public QoS
{
public:
  ServicesQoS();
};

class ParametersQoS : public QoS
{
public:
  ParametersQoS();
};

class CallbackGroup
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(CallbackGroup)
};

enum class CallbackGroupType { MutuallyExclusive, Reentrant };

class NodeOptions
{
public:
  NodeOptions();
  NodeOptions & use_intra_process_comms(bool value);
  NodeOptions & allow_undeclared_parameters(bool value);
  NodeOptions & automatically_declare_parameters_from_overrides(bool value);
  NodeOptions & arguments(const std::vector<std::string> & arguments);
};

template<class AllocatorT = std::allocator<void>>
class PublisherOptionsWithAllocator
{
public:
  PublisherOptionsWithAllocator();
};
using PublisherOptions = PublisherOptionsWithAllocator<std::allocator<void>>;

template<class AllocatorT = std::allocator<void>>
class SubscriptionOptionsWithAllocator
{
public:
  SubscriptionOptionsWithAllocator();
  CallbackGroup::SharedPtr callback_group;
};
using SubscriptionOptions = SubscriptionOptionsWithAllocator<std::allocator<void>>;

class SerializedMessage
{
public:
  SerializedMessage();
};

class MessageInfo
{
};

template<class MessageT, class AllocatorT = std::allocator<void>>
class LoanedMessage
{
public:
  MessageT & get() const;
};

class PublisherBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(PublisherBase)
  const char * get_topic_name() const;
  std::size_t get_subscription_count() const;
};

template<class MessageT, class AllocatorT = std::allocator<void>>
class Publisher : public PublisherBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Publisher)
  void publish(std::unique_ptr<MessageT> msg);
  void publish(const MessageT & msg);
  void publish(const SerializedMessage & serialized_msg);
  void publish(LoanedMessage<MessageT, AllocatorT> && loaned_msg);
  LoanedMessage<MessageT, AllocatorT> borrow_loaned_message();
};

class GenericPublisher : public PublisherBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericPublisher)
  void publish(const SerializedMessage & message);
};

class SubscriptionBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(SubscriptionBase)
  const char * get_topic_name() const;
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

class TimerBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(TimerBase)
  void cancel();
  void reset();
  bool is_canceled();
};

template<class FunctorT>
class GenericTimer : public TimerBase
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericTimer)
};

template<class FunctorT>
class WallTimer : public GenericTimer<FunctorT>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(WallTimer)
};

template<class ServiceT>
class Service
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Service)
};

template<class ServiceT>
class Client
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Client)
  using SharedRequest = std::shared_ptr<typename ServiceT::Request>;
  template<class RepT, class RatioT>
  bool wait_for_service(std::chrono::duration<RepT, RatioT> timeout);
  template<class RequestT>
  void async_send_request(RequestT && request);
  template<class RequestT, class CallbackT>
  void async_send_request(RequestT && request, CallbackT && callback);
};

class Parameter
{
public:
  template<class T>
  T get_value() const;
  double as_double() const;
  int64_t as_int() const;
  bool as_bool() const;
  std::string as_string() const;
};

class ParameterValue
{
public:
  template<class T>
  T get() const;
};

namespace node_interfaces
{
class NodeBaseInterface
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(NodeBaseInterface)
};
class NodeTimersInterface
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(NodeTimersInterface)
};
class NodeTopicsInterface
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(NodeTopicsInterface)
};
class NodeClockInterface
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(NodeClockInterface)
};
}  // namespace node_interfaces

class Node : public std::enable_shared_from_this<Node>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(Node)

  explicit Node(const std::string & node_name,
                const NodeOptions & options = NodeOptions());
  explicit Node(const std::string & node_name, const std::string & namespace_,
                const NodeOptions & options = NodeOptions());
  virtual ~Node();

  const char * get_name() const;
  const char * get_namespace() const;
  Logger get_logger() const;
  Clock::SharedPtr get_clock();
  Time now() const;
  Node::SharedPtr create_sub_node(const std::string & sub_namespace);
  CallbackGroup::SharedPtr create_callback_group(CallbackGroupType type);

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

  template<class DurationRepT = int64_t, class DurationT = std::milli,
    class CallbackT>
  typename WallTimer<CallbackT>::SharedPtr create_wall_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    CallbackGroup::SharedPtr group = nullptr, bool autostart = true);

  template<class DurationRepT = int64_t, class DurationT = std::milli,
    class CallbackT>
  typename GenericTimer<CallbackT>::SharedPtr create_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    CallbackGroup::SharedPtr group = nullptr);

  template<class ServiceT, class CallbackT>
  typename Service<ServiceT>::SharedPtr create_service(
    const std::string & service_name, CallbackT && callback,
    const QoS & qos = ServicesQoS(), CallbackGroup::SharedPtr group = nullptr);

  template<class ServiceT>
  typename Client<ServiceT>::SharedPtr create_client(
    const std::string & service_name, const QoS & qos = ServicesQoS(),
    CallbackGroup::SharedPtr group = nullptr);

  template<class AllocatorT = std::allocator<void>>
  std::shared_ptr<GenericPublisher> create_generic_publisher(
    const std::string & topic_name, const std::string & topic_type,
    const QoS & qos,
    const PublisherOptionsWithAllocator<AllocatorT> & options =
    PublisherOptionsWithAllocator<AllocatorT>());

  template<class CallbackT, class AllocatorT = std::allocator<void>>
  std::shared_ptr<GenericSubscription> create_generic_subscription(
    const std::string & topic_name, const std::string & topic_type,
    const QoS & qos, CallbackT && callback,
    const SubscriptionOptionsWithAllocator<AllocatorT> & options =
    SubscriptionOptionsWithAllocator<AllocatorT>());

  template<class ParameterT>
  ParameterT declare_parameter(const std::string & name,
                               const ParameterT & default_value);
  template<class ParameterT>
  ParameterT declare_parameter(const std::string & name);
  Parameter get_parameter(const std::string & name) const;
  template<class ParameterT>
  bool get_parameter(const std::string & name, ParameterT & parameter) const;
  template<class ParameterT>
  bool get_parameter_or(const std::string & name, ParameterT & value,
                        const ParameterT & alternative) const;

  node_interfaces::NodeBaseInterface::SharedPtr get_node_base_interface();
  node_interfaces::NodeTimersInterface::SharedPtr get_node_timers_interface();
  node_interfaces::NodeTopicsInterface::SharedPtr get_node_topics_interface();
  node_interfaces::NodeClockInterface::SharedPtr get_node_clock_interface();
};

// free functions (create_publisher.hpp, create_subscription.hpp,
// create_timer.hpp)
template<class MessageT, class AllocatorT = std::allocator<void>,
  class PublisherT = Publisher<MessageT, AllocatorT>, class NodeT>
std::shared_ptr<PublisherT> create_publisher(
  NodeT && node, const std::string & topic_name, const QoS & qos,
  const PublisherOptionsWithAllocator<AllocatorT> & options =
  PublisherOptionsWithAllocator<AllocatorT>());

template<class MessageT, class CallbackT,
  class AllocatorT = std::allocator<void>,
  class SubscriptionT = Subscription<MessageT, AllocatorT>, class NodeT>
std::shared_ptr<SubscriptionT> create_subscription(
  NodeT && node, const std::string & topic_name, const QoS & qos,
  CallbackT && callback,
  const SubscriptionOptionsWithAllocator<AllocatorT> & options =
  SubscriptionOptionsWithAllocator<AllocatorT>());

template<class NodeT, class CallbackT>
TimerBase::SharedPtr create_timer(
  NodeT node, Clock::SharedPtr clock, Duration period, CallbackT && callback,
  CallbackGroup::SharedPtr group = nullptr);

template<class CallbackT>
TimerBase::SharedPtr create_timer(
  std::shared_ptr<node_interfaces::NodeBaseInterface> node_base,
  std::shared_ptr<node_interfaces::NodeTimersInterface> node_timers,
  Clock::SharedPtr clock, Duration period, CallbackT && callback,
  CallbackGroup::SharedPtr group = nullptr);

// rate.hpp (the Humble shape: Rate and WallRate are GenericRate)
template<class ClockT = std::chrono::high_resolution_clock>
class GenericRate
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(GenericRate)
  explicit GenericRate(double rate);
  explicit GenericRate(std::chrono::nanoseconds period);
  bool sleep();
  void reset();
  std::chrono::nanoseconds period() const;
};
using Rate = GenericRate<std::chrono::system_clock>;
using WallRate = GenericRate<std::chrono::steady_clock>;

// executors
class Executor
{
public:
  void add_node(Node::SharedPtr node);
  void add_node(node_interfaces::NodeBaseInterface::SharedPtr node);
  void remove_node(Node::SharedPtr node);
  void spin();
  void spin_some();
  void cancel();
};

namespace executors
{
class SingleThreadedExecutor : public Executor
{
public:
  SingleThreadedExecutor();
};
class MultiThreadedExecutor : public Executor
{
public:
  MultiThreadedExecutor();
};
}  // namespace executors

void spin(Node::SharedPtr node_ptr);
void spin(node_interfaces::NodeBaseInterface::SharedPtr node_ptr);
void spin_some(Node::SharedPtr node_ptr);

}  // namespace rclcpp

// logging macros: the arguments stay expressions in a do/while(0) like the
// real expansion
void rsia_model_rclcpp_log(...);
#define RSIA_MODEL_RCLCPP_LOG(logger, ...) \
  do { rsia_model_rclcpp_log(logger, __VA_ARGS__); } while (0)
#define RCLCPP_DEBUG(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_WARN(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_ERROR(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_FATAL(logger, ...) RSIA_MODEL_RCLCPP_LOG(logger, __VA_ARGS__)
#define RCLCPP_INFO_STREAM(logger, stream) \
  RSIA_MODEL_RCLCPP_LOG(logger, 0)
#define RCLCPP_WARN_STREAM(logger, stream) \
  RSIA_MODEL_RCLCPP_LOG(logger, 0)
#define RCLCPP_ERROR_STREAM(logger, stream) \
  RSIA_MODEL_RCLCPP_LOG(logger, 0)
#define RCLCPP_INFO_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)
#define RCLCPP_WARN_THROTTLE(logger, clock, ms, ...) \
  RSIA_MODEL_RCLCPP_LOG(logger, clock, ms, __VA_ARGS__)

#endif  // RSIA_MODEL_RCLCPP_RCLCPP_HPP
