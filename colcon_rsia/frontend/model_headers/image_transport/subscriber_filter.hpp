// colcon-rsia model of <image_transport/subscriber_filter.hpp> (ROS 2): an
// image subscriber usable as a message_filters input; its topic is the
// constructor's (or subscribe's) second argument, after the node.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_SUBSCRIBER_FILTER_HPP
#define RSIA_MODEL_IMAGE_TRANSPORT_SUBSCRIBER_FILTER_HPP

#include <string>

#include <rclcpp/rclcpp.hpp>
#include <message_filters/simple_filter.hpp>
#include <sensor_msgs/msg/image.hpp>
#include <image_transport/subscriber.hpp>

namespace image_transport
{

class SubscriberFilter : public message_filters::SimpleFilter<sensor_msgs::msg::Image>
{
public:
  SubscriberFilter(
    rclcpp::Node * node, const std::string & base_topic,
    const std::string & transport);
  SubscriberFilter();
  ~SubscriberFilter();

  void subscribe(
    rclcpp::Node * node, const std::string & base_topic,
    const std::string & transport,
    rmw_qos_profile_t custom_qos = rmw_qos_profile_default,
    rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  void unsubscribe();
  std::string getTopic() const;
  size_t getNumPublishers() const;
  void shutdown();
  const Subscriber & getSubscriber() const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_SUBSCRIBER_FILTER_HPP
