// colcon-rsia model of <ros/advertise_service_options.h>.
#ifndef RSIA_MODEL_ROS_ADVERTISE_SERVICE_OPTIONS_H
#define RSIA_MODEL_ROS_ADVERTISE_SERVICE_OPTIONS_H

#include <string>

#include <boost/function.hpp>
#include <ros/common.h>
#include <ros/forwards.h>
#include <ros/service_callback_helper.h>

namespace ros
{

struct AdvertiseServiceOptions
{
  AdvertiseServiceOptions();

  template <class MReq, class MRes>
  void init(const std::string& _service, const boost::function<bool(MReq&, MRes&)>& _callback);
  template <class Service>
  void init(const std::string& _service,
            const boost::function<bool(typename Service::Request&, typename Service::Response&)>& _callback);
  template <class Spec>
  void initBySpecType(const std::string& _service, const typename Spec::CallbackType& _callback);

  template <class Service>
  static AdvertiseServiceOptions create(
      const std::string& service,
      const boost::function<bool(typename Service::Request&, typename Service::Response&)>& callback,
      const VoidConstPtr& tracked_object, CallbackQueueInterface* queue);

  std::string service;
  std::string md5sum;
  std::string datatype;
  std::string req_datatype;
  std::string res_datatype;
  CallbackQueueInterface* callback_queue;
  VoidConstPtr tracked_object;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_ADVERTISE_SERVICE_OPTIONS_H
