// colcon-rsia model of <ros/service.h>: the ros::service free functions.
#ifndef RSIA_MODEL_ROS_SERVICE_H
#define RSIA_MODEL_ROS_SERVICE_H

#include <cstdint>
#include <string>

#include <ros/common.h>
#include <ros/node_handle.h>
#include <ros/service_client.h>

namespace ros
{

namespace service
{

template <class MReq, class MRes>
bool call(const std::string& service_name, MReq& req, MRes& res);
template <class Service>
bool call(const std::string& service_name, Service& service);

bool waitForService(const std::string& service_name, int32_t timeout);
bool waitForService(const std::string& service_name, ros::Duration timeout = ros::Duration(-1));
bool exists(const std::string& service_name, bool print_failure_reason);

template <class MReq, class MRes>
ServiceClient createClient(const std::string& service_name, bool persistent = false,
                           const M_string& header_values = M_string());
template <class Service>
ServiceClient createClient(const std::string& service_name, bool persistent = false,
                           const M_string& header_values = M_string());

}  // namespace service

}  // namespace ros

#endif  // RSIA_MODEL_ROS_SERVICE_H
