// colcon-rsia model of <ros/advertise_options.h>.
#ifndef RSIA_MODEL_ROS_ADVERTISE_OPTIONS_H
#define RSIA_MODEL_ROS_ADVERTISE_OPTIONS_H

#include <cstdint>
#include <string>

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

struct AdvertiseOptions
{
  AdvertiseOptions();
  AdvertiseOptions(const std::string& _topic, uint32_t _queue_size, const std::string& _md5sum,
                   const std::string& _datatype, const std::string& _message_definition,
                   const SubscriberStatusCallback& _connect_cb = SubscriberStatusCallback(),
                   const SubscriberStatusCallback& _disconnect_cb = SubscriberStatusCallback());

  template <class M>
  void init(const std::string& _topic, uint32_t _queue_size,
            const SubscriberStatusCallback& _connect_cb = SubscriberStatusCallback(),
            const SubscriberStatusCallback& _disconnect_cb = SubscriberStatusCallback());

  template <class M>
  static AdvertiseOptions create(const std::string& topic, uint32_t queue_size,
                                 const SubscriberStatusCallback& connect_cb,
                                 const SubscriberStatusCallback& disconnect_cb,
                                 const VoidConstPtr& tracked_object, CallbackQueueInterface* queue);

  std::string topic;
  uint32_t queue_size;
  std::string md5sum;
  std::string datatype;
  std::string message_definition;
  SubscriberStatusCallback connect_cb;
  SubscriberStatusCallback disconnect_cb;
  CallbackQueueInterface* callback_queue;
  VoidConstPtr tracked_object;
  bool latch;
  bool has_header;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_ADVERTISE_OPTIONS_H
