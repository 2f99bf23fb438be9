// colcon-rsia model of <ros/subscribe_options.h>.
#ifndef RSIA_MODEL_ROS_SUBSCRIBE_OPTIONS_H
#define RSIA_MODEL_ROS_SUBSCRIBE_OPTIONS_H

#include <cstdint>
#include <string>

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/common.h>
#include <ros/message_event.h>
#include <ros/transport_hints.h>

namespace ros
{

struct SubscribeOptions
{
  SubscribeOptions();
  SubscribeOptions(const std::string& _topic, uint32_t _queue_size, const std::string& _md5sum,
                   const std::string& _datatype);

  template <class P>
  void initByFullCallbackType(const std::string& _topic, uint32_t _queue_size,
                              const boost::function<void(P)>& _callback);
  template <class M>
  void init(const std::string& _topic, uint32_t _queue_size,
            const boost::function<void(const boost::shared_ptr<M const>&)>& _callback);

  template <class M>
  static SubscribeOptions create(const std::string& topic, uint32_t queue_size,
                                 const boost::function<void(const boost::shared_ptr<M const>&)>& callback,
                                 const VoidConstPtr& tracked_object, CallbackQueueInterface* queue);

  std::string topic;
  uint32_t queue_size;
  std::string md5sum;
  std::string datatype;
  CallbackQueueInterface* callback_queue;
  bool allow_concurrent_callbacks;
  VoidConstPtr tracked_object;
  TransportHints transport_hints;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_SUBSCRIBE_OPTIONS_H
