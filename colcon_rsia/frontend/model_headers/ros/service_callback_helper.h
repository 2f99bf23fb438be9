// colcon-rsia model of <ros/service_callback_helper.h>: ros::ServiceEvent, a
// service callback parameter type (it appears in callback USRs).
#ifndef RSIA_MODEL_ROS_SERVICE_CALLBACK_HELPER_H
#define RSIA_MODEL_ROS_SERVICE_CALLBACK_HELPER_H

#include <string>

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/forwards.h>

namespace ros
{

template <typename MReq, typename MRes>
class ServiceEvent
{
public:
  typedef MReq RequestType;
  typedef MRes ResponseType;
  typedef boost::shared_ptr<RequestType> RequestPtr;
  typedef boost::shared_ptr<ResponseType> ResponsePtr;
  typedef boost::function<bool(ServiceEvent<RequestType, ResponseType>&)> CallbackType;

  ServiceEvent(const boost::shared_ptr<MReq const>& req, const boost::shared_ptr<MRes>& res,
               const boost::shared_ptr<M_string>& connection_header);

  const RequestType& getRequest() const;
  ResponseType& getResponse() const;
  M_string& getConnectionHeader() const;
  const std::string& getCallerName() const;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_SERVICE_CALLBACK_HELPER_H
