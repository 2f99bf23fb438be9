// colcon-rsia model of <dynamic_reconfigure/server.h>: a reconfigure server
// whose callback receives the package's generated <pkg/NameConfig.h> config.
#ifndef RSIA_MODEL_DYNAMIC_RECONFIGURE_SERVER_H
#define RSIA_MODEL_DYNAMIC_RECONFIGURE_SERVER_H

#include <cstdint>

#include <boost/function.hpp>
#include <boost/thread/recursive_mutex.hpp>
#include <ros/node_handle.h>

namespace dynamic_reconfigure
{

template <class ConfigType>
class Server
{
public:
  typedef boost::function<void(ConfigType&, uint32_t level)> CallbackType;

  Server(const ros::NodeHandle& nh = ros::NodeHandle("~"));
  Server(boost::recursive_mutex& mutex, const ros::NodeHandle& nh = ros::NodeHandle("~"));

  void setCallback(const CallbackType& callback);
  void clearCallback();
  void updateConfig(const ConfigType& config);
  void getConfigMax(ConfigType& config);
  void getConfigMin(ConfigType& config);
  void getConfigDefault(ConfigType& config);
  void setConfigMax(const ConfigType& config);
  void setConfigMin(const ConfigType& config);
  void setConfigDefault(const ConfigType& config);
};

}  // namespace dynamic_reconfigure

#endif  // RSIA_MODEL_DYNAMIC_RECONFIGURE_SERVER_H
