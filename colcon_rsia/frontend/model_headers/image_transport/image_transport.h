// colcon-rsia model of <image_transport/image_transport.h>: ImageTransport with
// its advertise, subscribe, advertiseCamera and subscribeCamera overloads.
#ifndef RSIA_MODEL_IMAGE_TRANSPORT_IMAGE_TRANSPORT_H
#define RSIA_MODEL_IMAGE_TRANSPORT_IMAGE_TRANSPORT_H

#include <cstdint>
#include <string>
#include <vector>

#include <boost/bind/bind.hpp>
#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <image_transport/camera_publisher.h>
#include <image_transport/camera_subscriber.h>
#include <image_transport/publisher.h>
#include <image_transport/subscriber.h>
#include <image_transport/transport_hints.h>
#include <ros/ros.h>

namespace image_transport
{

class ImageTransport
{
public:
  explicit ImageTransport(const ros::NodeHandle& nh);
  ~ImageTransport();

  Publisher advertise(const std::string& base_topic, uint32_t queue_size, bool latch = false);
  Publisher advertise(const std::string& base_topic, uint32_t queue_size,
                      const SubscriberStatusCallback& connect_cb,
                      const SubscriberStatusCallback& disconnect_cb = SubscriberStatusCallback(),
                      const ros::VoidPtr& tracked_object = ros::VoidPtr(), bool latch = false);

  Subscriber subscribe(const std::string& base_topic, uint32_t queue_size,
                       const boost::function<void(const sensor_msgs::ImageConstPtr&)>& callback,
                       const ros::VoidPtr& tracked_object = ros::VoidPtr(),
                       const TransportHints& transport_hints = TransportHints());
  Subscriber subscribe(const std::string& base_topic, uint32_t queue_size,
                       void (*fp)(const sensor_msgs::ImageConstPtr&),
                       const TransportHints& transport_hints = TransportHints());
  template <class T>
  Subscriber subscribe(const std::string& base_topic, uint32_t queue_size,
                       void (T::*fp)(const sensor_msgs::ImageConstPtr&), T* obj,
                       const TransportHints& transport_hints = TransportHints());
  template <class T>
  Subscriber subscribe(const std::string& base_topic, uint32_t queue_size,
                       void (T::*fp)(const sensor_msgs::ImageConstPtr&), const boost::shared_ptr<T>& obj,
                       const TransportHints& transport_hints = TransportHints());

  CameraPublisher advertiseCamera(const std::string& base_topic, uint32_t queue_size, bool latch = false);
  CameraPublisher advertiseCamera(const std::string& base_topic, uint32_t queue_size,
                                  const SubscriberStatusCallback& image_connect_cb,
                                  const SubscriberStatusCallback& image_disconnect_cb = SubscriberStatusCallback(),
                                  const ros::SubscriberStatusCallback& info_connect_cb =
                                      ros::SubscriberStatusCallback(),
                                  const ros::SubscriberStatusCallback& info_disconnect_cb =
                                      ros::SubscriberStatusCallback(),
                                  const ros::VoidPtr& tracked_object = ros::VoidPtr(), bool latch = false);

  CameraSubscriber subscribeCamera(const std::string& base_topic, uint32_t queue_size,
                                   const CameraSubscriber::Callback& callback,
                                   const ros::VoidPtr& tracked_object = ros::VoidPtr(),
                                   const TransportHints& transport_hints = TransportHints());
  CameraSubscriber subscribeCamera(const std::string& base_topic, uint32_t queue_size,
                                   void (*fp)(const sensor_msgs::ImageConstPtr&,
                                              const sensor_msgs::CameraInfoConstPtr&),
                                   const TransportHints& transport_hints = TransportHints());
  template <class T>
  CameraSubscriber subscribeCamera(const std::string& base_topic, uint32_t queue_size,
                                   void (T::*fp)(const sensor_msgs::ImageConstPtr&,
                                                 const sensor_msgs::CameraInfoConstPtr&),
                                   T* obj, const TransportHints& transport_hints = TransportHints());
  template <class T>
  CameraSubscriber subscribeCamera(const std::string& base_topic, uint32_t queue_size,
                                   void (T::*fp)(const sensor_msgs::ImageConstPtr&,
                                                 const sensor_msgs::CameraInfoConstPtr&),
                                   const boost::shared_ptr<T>& obj,
                                   const TransportHints& transport_hints = TransportHints());

  std::vector<std::string> getDeclaredTransports() const;
  std::vector<std::string> getLoadableTransports() const;
};

}  // namespace image_transport

#endif  // RSIA_MODEL_IMAGE_TRANSPORT_IMAGE_TRANSPORT_H
