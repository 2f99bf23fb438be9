// colcon-rsia model of <nodelet/loader.h>: nodelet::Loader, which a process
// uses to load nodelets itself. load(name, type, remappings, my_argv)
// starts an instance of the nodelet `type` named `name`.
#ifndef RSIA_MODEL_NODELET_LOADER_H
#define RSIA_MODEL_NODELET_LOADER_H

#include <map>
#include <string>
#include <vector>

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <nodelet/nodelet.h>

namespace ros
{

class NodeHandle;

}  // namespace ros

namespace nodelet
{

class Loader
{
public:
  explicit Loader(bool provide_ros_api = true);
  explicit Loader(const ros::NodeHandle& server_nh);
  explicit Loader(const boost::function<boost::shared_ptr<Nodelet>(const std::string& lookup_name)>& create_instance);
  ~Loader();

  bool load(const std::string& name, const std::string& type, const M_string& remappings,
            const V_string& my_argv);
  bool unload(const std::string& name);
  bool clear();
  std::vector<std::string> listLoadedNodelets();
};

}  // namespace nodelet

#endif  // RSIA_MODEL_NODELET_LOADER_H
