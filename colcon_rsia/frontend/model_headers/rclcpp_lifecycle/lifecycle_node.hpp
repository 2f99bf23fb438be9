// colcon-rsia model of <rclcpp_lifecycle/lifecycle_node.hpp> (ROS 2):
// written from the documented signatures (ros-api.md section 2.5).
#ifndef RSIA_MODEL_RCLCPP_LIFECYCLE_LIFECYCLE_NODE_HPP
#define RSIA_MODEL_RCLCPP_LIFECYCLE_LIFECYCLE_NODE_HPP

#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_publisher.hpp>

namespace rclcpp_lifecycle
{

class State
{
public:
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
  rclcpp::Logger get_logger() const;
  rclcpp::Clock::SharedPtr get_clock();
  rclcpp::Time now() const;

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

  template<class DurationRepT = int64_t, class DurationT = std::milli,
    class CallbackT>
  typename rclcpp::WallTimer<CallbackT>::SharedPtr create_wall_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  template<class DurationRepT = int64_t, class DurationT = std::milli,
    class CallbackT>
  typename rclcpp::GenericTimer<CallbackT>::SharedPtr create_timer(
    std::chrono::duration<DurationRepT, DurationT> period, CallbackT callback,
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  template<class ServiceT, class CallbackT>
  typename rclcpp::Service<ServiceT>::SharedPtr create_service(
    const std::string & service_name, CallbackT && callback,
    const rclcpp::QoS & qos = rclcpp::ServicesQoS(),
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  template<class ServiceT>
  typename rclcpp::Client<ServiceT>::SharedPtr create_client(
    const std::string & service_name,
    const rclcpp::QoS & qos = rclcpp::ServicesQoS(),
    rclcpp::CallbackGroup::SharedPtr group = nullptr);

  template<class ParameterT>
  ParameterT declare_parameter(const std::string & name,
                               const ParameterT & default_value);
  rclcpp::Parameter get_parameter(const std::string & name) const;

  rclcpp::node_interfaces::NodeBaseInterface::SharedPtr
  get_node_base_interface();
};

}  // namespace rclcpp_lifecycle

#endif  // RSIA_MODEL_RCLCPP_LIFECYCLE_LIFECYCLE_NODE_HPP
