// colcon-rsia model of <ros/service_server.h>.
#ifndef RSIA_MODEL_ROS_SERVICE_SERVER_H
#define RSIA_MODEL_ROS_SERVICE_SERVER_H

#include <string>
#include <vector>

#include <ros/common.h>
#include <ros/forwards.h>

namespace ros
{

class ServiceServer
{
public:
  ServiceServer();
  ServiceServer(const ServiceServer& rhs);
  ~ServiceServer();
  ServiceServer& operator=(const ServiceServer& other) = default;

  void shutdown();
  std::string getService() const;
  operator void*() const;
  bool operator<(const ServiceServer& rhs) const;
  bool operator==(const ServiceServer& rhs) const;
  bool operator!=(const ServiceServer& rhs) const;
};

typedef std::vector<ServiceServer> V_ServiceServer;

}  // namespace ros

#endif  // RSIA_MODEL_ROS_SERVICE_SERVER_H
