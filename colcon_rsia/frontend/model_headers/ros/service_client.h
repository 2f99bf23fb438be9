// colcon-rsia model of <ros/service_client.h>.
#ifndef RSIA_MODEL_ROS_SERVICE_CLIENT_H
#define RSIA_MODEL_ROS_SERVICE_CLIENT_H

#include <string>

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

class ServiceClient
{
public:
  ServiceClient();
  ServiceClient(const std::string& service_name, bool persistent, const M_string& header_values,
                const std::string& service_md5sum);
  ServiceClient(const ServiceClient& rhs);
  ~ServiceClient();
  ServiceClient& operator=(const ServiceClient& other) = default;

  template <class MReq, class MRes>
  bool call(MReq& req, MRes& res);
  template <class MReq, class MRes>
  bool call(MReq& req, MRes& resp, const std::string& service_md5sum);
  template <class Service>
  bool call(Service& service);

  bool isValid() const;
  bool isPersistent() const;
  void shutdown();
  bool waitForExistence(ros::Duration timeout = ros::Duration(-1));
  bool exists();
  std::string getService();
  operator void*() const;
  bool operator<(const ServiceClient& rhs) const;
  bool operator==(const ServiceClient& rhs) const;
  bool operator!=(const ServiceClient& rhs) const;
};

typedef boost::shared_ptr<ServiceClient> ServiceClientPtr;

}  // namespace ros

#endif  // RSIA_MODEL_ROS_SERVICE_CLIENT_H
