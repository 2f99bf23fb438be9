// colcon-rsia model of <ros/init.h>: ros::init, spin, ok, shutdown.
#ifndef RSIA_MODEL_ROS_INIT_H
#define RSIA_MODEL_ROS_INIT_H

#include <cstdint>
#include <string>

#include <ros/forwards.h>
#include <ros/spinner.h>

namespace ros
{

namespace init_options
{

enum InitOption
{
  NoSigintHandler = 1 << 0,
  AnonymousName = 1 << 1,
  NoRosout = 1 << 2,
};

}  // namespace init_options
typedef init_options::InitOption InitOption;

void init(int& argc, char** argv, const std::string& name, uint32_t options = 0);
void init(const M_string& remappings, const std::string& name, uint32_t options = 0);
void init(const VP_string& remapping_args, const std::string& name, uint32_t options = 0);
bool isInitialized();
bool isShuttingDown();
void spin();
void spin(Spinner& spinner);
void spinOnce();
void waitForShutdown();
bool ok();
void shutdown();
void requestShutdown();
void start();
bool isStarted();
CallbackQueue* getGlobalCallbackQueue();
std::string getROSArg(int argc, const char* const* argv, const std::string& arg);
void removeROSArgs(int argc, const char* const* argv, V_string& args_out);
const std::string& getDefaultMasterURI();

}  // namespace ros

#endif  // RSIA_MODEL_ROS_INIT_H
