// colcon-rsia model of <rclcpp_lifecycle/lifecycle_node.hpp> (ROS 2):
// written from the documented signatures (the rclcpp_lifecycle API
// documentation).
#ifndef RSIA_MODEL_RCLCPP_LIFECYCLE_LIFECYCLE_NODE_HPP
#define RSIA_MODEL_RCLCPP_LIFECYCLE_LIFECYCLE_NODE_HPP

#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_publisher.hpp>

namespace rclcpp_lifecycle
{

class State
{
public:
  State();
  State(uint8_t id, const std::string & label);
  uint8_t id() const;
  std::string label() const;
};

namespace node_interfaces
{
class LifecycleNodeInterface
{
public:
  enum class CallbackReturn { SUCCESS, FAILURE, ERROR };
  virtual CallbackReturn on_configure(const State & previous_state);
  virtual CallbackReturn on_cleanup(const State & previous_state);
  virtual CallbackReturn on_shutdown(const State & previous_state);
  virtual CallbackReturn on_activate(const State & previous_state);
  virtual CallbackReturn on_deactivate(const State & previous_state);
  virtual CallbackReturn on_error(const State & previous_state);
  virtual ~LifecycleNodeInterface();
};
}  // namespace node_interfaces

class LifecycleNode
  : public node_interfaces::LifecycleNodeInterface,
  public std::enable_shared_from_this<LifecycleNode>
{
public:
  RCLCPP_SMART_PTR_DEFINITIONS(LifecycleNode)

  explicit LifecycleNode(
    const std::string & node_name,
    const rclcpp::NodeOptions & options = rclcpp::NodeOptions(),
    bool enable_communication_interface = true);
  LifecycleNode(
    const std::string & node_name, const std::string & namespace_,
    const rclcpp::NodeOptions & options = rclcpp::NodeOptions(),
    bool enable_communication_interface = true);
  virtual ~LifecycleNode();

  const char * get_name() const;
  const char * get_namespace() const;
  const char * get_fully_qualified_name() const;
  rclcpp::Logger get_logger() const;
  rclcpp::Clock::SharedPtr get_clock();
  rclcpp::Time now() const;
  rclcpp::CallbackGroup::SharedPtr create_callback_group(
    rclcpp::CallbackGroupType group_type,
    bool automatically_add_to_executor_with_node = true);

  template<class MessageT, class AllocatorT = std::allocator<void>>
  std::shared_ptr<LifecyclePublisher<MessageT, AllocatorT>> create_publisher(
    const std::string & topic_name, const rclcpp::QoS & qos,
    const rclcpp::PublisherOptionsWithAllocator<AllocatorT> & options =
    rclcpp::PublisherOptionsWithAllocator<AllocatorT>());

  template<class MessageT, class CallbackT,
    class AllocatorT = std::allocator<void>,
    class SubscriptionT = rclcpp::Subscription<MessageT, AllocatorT>>
  std::shared_ptr<SubscriptionT> create_subscription(
    const std::string & topic_name, const rclcpp::QoS & qos,
    CallbackT && callback,
    const rclcpp::SubscriptionOptionsWithAllocator<AllocatorT> & options =
    rclcpp::SubscriptionOptionsWithAllocator<AllocatorT>());

  // no `autostart` here in Humble/Jazzy/Rolling
  template<class DurationRepT = int64_t, class DurationT = std::milli,
    class CallbackT>
  typename rclcpp::WallTimer<CallbackT>::SharedPtr create_wall_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  // Jazzy+
  template<class DurationRepT = int64_t, class DurationT = std::milli,
    class CallbackT>
  typename rclcpp::GenericTimer<CallbackT>::SharedPtr create_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  // the rmw_qos_profile_t forms: Humble, deprecated in Jazzy
  template<class ServiceT, class CallbackT>
  typename rclcpp::Service<ServiceT>::SharedPtr create_service(
    const std::string & service_name, CallbackT && callback,
    const rmw_qos_profile_t & qos_profile,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);
  template<class ServiceT, class CallbackT>
  typename rclcpp::Service<ServiceT>::SharedPtr create_service(
    const std::string & service_name, CallbackT && callback,
    const rclcpp::QoS & qos = rclcpp::ServicesQoS(),
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  template<class ServiceT>
  typename rclcpp::Client<ServiceT>::SharedPtr create_client(
    const std::string & service_name, const rmw_qos_profile_t & qos_profile,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);
  template<class ServiceT>
  typename rclcpp::Client<ServiceT>::SharedPtr create_client(
    const std::string & service_name,
    const rclcpp::QoS & qos = rclcpp::ServicesQoS(),
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  template<class AllocatorT = std::allocator<void>>
  std::shared_ptr<rclcpp::GenericPublisher> create_generic_publisher(
    const std::string & topic_name, const std::string & topic_type,
    const rclcpp::QoS & qos,
    const rclcpp::PublisherOptionsWithAllocator<AllocatorT> & options =
    rclcpp::PublisherOptionsWithAllocator<AllocatorT>());

  template<class AllocatorT = std::allocator<void>>
  std::shared_ptr<rclcpp::GenericSubscription> create_generic_subscription(
    const std::string & topic_name, const std::string & topic_type,
    const rclcpp::QoS & qos,
    std::function<void(std::shared_ptr<rclcpp::SerializedMessage>)> callback,
    const rclcpp::SubscriptionOptionsWithAllocator<AllocatorT> & options =
    rclcpp::SubscriptionOptionsWithAllocator<AllocatorT>());

  const rclcpp::ParameterValue & declare_parameter(
    const std::string & name, const rclcpp::ParameterValue & default_value,
    const rcl_interfaces::msg::ParameterDescriptor & parameter_descriptor =
    rcl_interfaces::msg::ParameterDescriptor(),
    bool ignore_override = false);
  const rclcpp::ParameterValue & declare_parameter(
    const std::string & name, rclcpp::ParameterType type,
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
  bool has_parameter(const std::string & name) const;
  rclcpp::Parameter get_parameter(const std::string & name) const;
  bool get_parameter(const std::string & name,
                     rclcpp::Parameter & parameter) const;
  template<class ParameterT>
  bool get_parameter(const std::string & name, ParameterT & parameter) const;
  template<class ParameterT>
  bool get_parameter_or(const std::string & name, ParameterT & value,
                        const ParameterT & alternative_value) const;
  rcl_interfaces::msg::SetParametersResult set_parameter(
    const rclcpp::Parameter & parameter);
  RCUTILS_WARN_UNUSED
  rclcpp::node_interfaces::OnSetParametersCallbackHandle::SharedPtr
  add_on_set_parameters_callback(
    rclcpp::node_interfaces::NodeParametersInterface::OnSetParametersCallbackType
    callback);

  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr
  get_node_base_interface();
  rclcpp::node_interfaces::NodeClockInterface::SharedPtr
  get_node_clock_interface();
  rclcpp::node_interfaces::NodeGraphInterface::SharedPtr
  get_node_graph_interface();
  rclcpp::node_interfaces::NodeLoggingInterface::SharedPtr
  get_node_logging_interface();
  rclcpp::node_interfaces::NodeTimersInterface::SharedPtr
  get_node_timers_interface();
  rclcpp::node_interfaces::NodeTopicsInterface::SharedPtr
  get_node_topics_interface();
  rclcpp::node_interfaces::NodeServicesInterface::SharedPtr
  get_node_services_interface();
  rclcpp::node_interfaces::NodeParametersInterface::SharedPtr
  get_node_parameters_interface();
  rclcpp::node_interfaces::NodeWaitablesInterface::SharedPtr
  get_node_waitables_interface();

  // the state machine
  const State & get_current_state() const;
  const State & trigger_transition(uint8_t transition_id);
  const State & configure();
  const State & cleanup();
  const State & activate();
  const State & deactivate();
  const State & shutdown();
  bool register_on_configure(
    std::function<CallbackReturn(const State &)> fcn);
  bool register_on_cleanup(
    std::function<CallbackReturn(const State &)> fcn);
  bool register_on_shutdown(
    std::function<CallbackReturn(const State &)> fcn);
  bool register_on_activate(
    std::function<CallbackReturn(const State &)> fcn);
  bool register_on_deactivate(
    std::function<CallbackReturn(const State &)> fcn);
  bool register_on_error(
    std::function<CallbackReturn(const State &)> fcn);
  CallbackReturn on_activate(const State & previous_state) override;
  CallbackReturn on_deactivate(const State & previous_state) override;
};

}  // namespace rclcpp_lifecycle

#endif  // RSIA_MODEL_RCLCPP_LIFECYCLE_LIFECYCLE_NODE_HPP
