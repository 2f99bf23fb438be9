// colcon-rsia model of <ros/service_client_options.h>.
#ifndef RSIA_MODEL_ROS_SERVICE_CLIENT_OPTIONS_H
#define RSIA_MODEL_ROS_SERVICE_CLIENT_OPTIONS_H

#include <string>

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

struct ServiceClientOptions
{
  ServiceClientOptions();
  ServiceClientOptions(const std::string& _service, const std::string& _md5sum, bool _persistent,
                       const M_string& _header);

  template <class MReq, class MRes>
  void init(const std::string& _service, bool _persistent, const M_string& _header);
  template <class Service>
  void init(const std::string& _service, bool _persistent, const M_string& _header);

  std::string service;
  std::string md5sum;
  bool persistent;
  M_string header;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_SERVICE_CLIENT_OPTIONS_H
