// colcon-rsia model of <message_filters/subscriber.hpp> (ROS 2): a subscriber
// whose topic is its constructor's (or subscribe's) second argument, after
// the node. The union of the Humble, Jazzy and Rolling shapes: a node pointer
// or shared pointer of any node class (Humble's NodeType class parameter is
// kept), an rmw_qos_profile_t (H/J, deprecated in R) or an rclcpp::QoS
// (J/R), with or without SubscriptionOptions; Rolling's node-interfaces form
// takes the node itself.
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER
#define RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER

#include <memory>
#include <string>

#include <rclcpp/rclcpp.hpp>
#include <message_filters/connection.hpp>
#include <message_filters/simple_filter.hpp>

namespace message_filters
{

template<class NodeType = rclcpp::Node>
class SubscriberBase
{
public:
  virtual ~SubscriberBase();
  virtual void subscribe() = 0;
  virtual void unsubscribe() = 0;
};

template<class M, class NodeType = rclcpp::Node>
class Subscriber : public SubscriberBase<NodeType>, public SimpleFilter<M>
{
public:
  using NodePtr = std::shared_ptr<NodeType>;
  using MConstPtr = std::shared_ptr<M const>;
  using EventType = MessageEvent<M const>;

  template<typename NodeT>
  Subscriber(
    std::shared_ptr<NodeT> node, const std::string & topic,
    const rmw_qos_profile_t qos = rmw_qos_profile_default);
  template<typename NodeT>
  Subscriber(
    NodeT * node, const std::string & topic,
    const rmw_qos_profile_t qos = rmw_qos_profile_default);
  template<typename NodeT>
  Subscriber(
    std::shared_ptr<NodeT> node, const std::string & topic,
    const rmw_qos_profile_t qos, rclcpp::SubscriptionOptions options);
  template<typename NodeT>
  Subscriber(
    NodeT * node, const std::string & topic,
    const rmw_qos_profile_t qos, rclcpp::SubscriptionOptions options);
  template<typename NodeT>
  Subscriber(
    std::shared_ptr<NodeT> node, const std::string & topic,
    const rclcpp::QoS & qos);
  template<typename NodeT>
  Subscriber(NodeT * node, const std::string & topic, const rclcpp::QoS & qos);
  template<typename NodeT>
  Subscriber(
    std::shared_ptr<NodeT> node, const std::string & topic,
    const rclcpp::QoS & qos, rclcpp::SubscriptionOptions options);
  template<typename NodeT>
  Subscriber(
    NodeT * node, const std::string & topic, const rclcpp::QoS & qos,
    rclcpp::SubscriptionOptions options);
  // Rolling: RequiredInterfaces, made from the node object itself
  template<typename NodeT>
  Subscriber(NodeT & node, const std::string & topic, const rclcpp::QoS & qos);
  template<typename NodeT>
  Subscriber(
    NodeT & node, const std::string & topic, const rclcpp::QoS & qos,
    rclcpp::SubscriptionOptions options);
  Subscriber();
  ~Subscriber();

  template<typename NodeT>
  void subscribe(
    std::shared_ptr<NodeT> node, const std::string & topic,
    const rmw_qos_profile_t qos = rmw_qos_profile_default);
  template<typename NodeT>
  void subscribe(
    NodeT * node, const std::string & topic,
    const rmw_qos_profile_t qos = rmw_qos_profile_default);
  template<typename NodeT>
  void subscribe(
    std::shared_ptr<NodeT> node, const std::string & topic,
    const rmw_qos_profile_t qos, rclcpp::SubscriptionOptions options);
  template<typename NodeT>
  void subscribe(
    NodeT * node, const std::string & topic, const rmw_qos_profile_t qos,
    rclcpp::SubscriptionOptions options);
  template<typename NodeT>
  void subscribe(
    std::shared_ptr<NodeT> node, const std::string & topic,
    const rclcpp::QoS & qos);
  template<typename NodeT>
  void subscribe(NodeT * node, const std::string & topic, const rclcpp::QoS & qos);
  template<typename NodeT>
  void subscribe(
    std::shared_ptr<NodeT> node, const std::string & topic,
    const rclcpp::QoS & qos, rclcpp::SubscriptionOptions options);
  template<typename NodeT>
  void subscribe(
    NodeT * node, const std::string & topic, const rclcpp::QoS & qos,
    rclcpp::SubscriptionOptions options);
  template<typename NodeT>
  void subscribe(NodeT & node, const std::string & topic, const rclcpp::QoS & qos);
  template<typename NodeT>
  void subscribe(
    NodeT & node, const std::string & topic, const rclcpp::QoS & qos,
    rclcpp::SubscriptionOptions options);
  void subscribe();
  void unsubscribe();

  std::string getTopic() const;
  const typename rclcpp::Subscription<M>::SharedPtr getSubscriber() const;
  template<typename F>
  void connectInput(F & f);
  void add(const EventType & e);
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SUBSCRIBER
