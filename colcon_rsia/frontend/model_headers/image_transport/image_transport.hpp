// colcon-rsia model of <image_transport/image_transport.hpp> (ROS 2,
// Humble/Jazzy/Rolling): the free functions create_publisher,
// create_subscription, create_camera_publisher, create_camera_subscription
// (node pointer first, then the base topic) and class ImageTransport, made
// from a node shared pointer, with the advertise/subscribe overload sets.
// The rmw_qos_profile_t forms of advertise and subscribe are Jazzy+; Humble's
// subscribe forms are the queue_size ones, with or without options.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_IMAGE_TRANSPORT_HPP
#define RSIA_MODEL_IMAGE_TRANSPORT_IMAGE_TRANSPORT_HPP

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/camera_info.hpp>
#include <sensor_msgs/msg/image.hpp>
#include <image_transport/camera_publisher.hpp>
#include <image_transport/camera_subscriber.hpp>
#include <image_transport/publisher.hpp>
#include <image_transport/subscriber.hpp>
#include <image_transport/transport_hints.hpp>

namespace image_transport
{

Publisher create_publisher(
  rclcpp::Node * node,
  const std::string & base_topic,
  rmw_qos_profile_t custom_qos = rmw_qos_profile_default,
  rclcpp::PublisherOptions options = rclcpp::PublisherOptions());

Subscriber create_subscription(
  rclcpp::Node * node,
  const std::string & base_topic,
  const Subscriber::Callback & callback,
  const std::string & transport,
  rmw_qos_profile_t custom_qos = rmw_qos_profile_default,
  rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());

CameraPublisher create_camera_publisher(
  rclcpp::Node * node,
  const std::string & base_topic,
  rmw_qos_profile_t custom_qos = rmw_qos_profile_default,
  rclcpp::PublisherOptions pub_options = rclcpp::PublisherOptions());

CameraSubscriber create_camera_subscription(
  rclcpp::Node * node,
  const std::string & base_topic,
  const CameraSubscriber::Callback & callback,
  const std::string & transport,
  rmw_qos_profile_t custom_qos = rmw_qos_profile_default);

std::vector<std::string> getDeclaredTransports();
std::vector<std::string> getLoadableTransports();

class ImageTransport
{
public:
  using VoidPtr = std::shared_ptr<void>;
  using ImageConstPtr = sensor_msgs::msg::Image::ConstSharedPtr;
  using CameraInfoConstPtr = sensor_msgs::msg::CameraInfo::ConstSharedPtr;

  explicit ImageTransport(rclcpp::Node::SharedPtr node);
  ~ImageTransport();

  Publisher advertise(
    const std::string & base_topic, uint32_t queue_size, bool latch = false);
  Publisher advertise(
    const std::string & base_topic, rmw_qos_profile_t custom_qos,
    bool latch = false);

  Subscriber subscribe(
    const std::string & base_topic, uint32_t queue_size,
    const Subscriber::Callback & callback,
    const VoidPtr & tracked_object = VoidPtr(),
    const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  Subscriber subscribe(
    const std::string & base_topic, uint32_t queue_size,
    void (* fp)(const ImageConstPtr &),
    const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  template<class T>
  Subscriber subscribe(
    const std::string & base_topic, uint32_t queue_size,
    void (T::* fp)(const ImageConstPtr &), T * obj,
    const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  template<class T>
  Subscriber subscribe(
    const std::string & base_topic, uint32_t queue_size,
    void (T::* fp)(const ImageConstPtr &), const std::shared_ptr<T> & obj,
    const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  Subscriber subscribe(
    const std::string & base_topic, rmw_qos_profile_t custom_qos,
    const Subscriber::Callback & callback,
    const VoidPtr & tracked_object,
    const TransportHints * transport_hints,
    const rclcpp::SubscriptionOptions options);
  Subscriber subscribe(
    const std::string & base_topic, rmw_qos_profile_t custom_qos,
    void (* fp)(const ImageConstPtr &),
    const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  template<class T>
  Subscriber subscribe(
    const std::string & base_topic, rmw_qos_profile_t custom_qos,
    void (T::* fp)(const ImageConstPtr &), T * obj,
    const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());
  template<class T>
  Subscriber subscribe(
    const std::string & base_topic, rmw_qos_profile_t custom_qos,
    void (T::* fp)(const ImageConstPtr &), const std::shared_ptr<T> & obj,
    const TransportHints * transport_hints = nullptr,
    const rclcpp::SubscriptionOptions options = rclcpp::SubscriptionOptions());

  CameraPublisher advertiseCamera(
    const std::string & base_topic, uint32_t queue_size, bool latch = false);

  CameraSubscriber subscribeCamera(
    const std::string & base_topic, uint32_t queue_size,
    const CameraSubscriber::Callback & callback,
    const VoidPtr & tracked_object = VoidPtr(),
    const TransportHints * transport_hints = nullptr);
  CameraSubscriber subscribeCamera(
    const std::string & base_topic, uint32_t queue_size,
    void (* fp)(const ImageConstPtr &, const CameraInfoConstPtr &),
    const TransportHints * transport_hints = nullptr);
  template<class T>
  CameraSubscriber subscribeCamera(
    const std::string & base_topic, uint32_t queue_size,
    void (T::* fp)(const ImageConstPtr &, const CameraInfoConstPtr &),
    T * obj, const TransportHints * transport_hints = nullptr);
  template<class T>
  CameraSubscriber subscribeCamera(
    const std::string & base_topic, uint32_t queue_size,
    void (T::* fp)(const ImageConstPtr &, const CameraInfoConstPtr &),
    const std::shared_ptr<T> & obj,
    const TransportHints * transport_hints = nullptr);

  std::vector<std::string> getDeclaredTransports() const;
  std::vector<std::string> getLoadableTransports() const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_IMAGE_TRANSPORT_HPP
