// A filters plugin: exported with pluginlib, but it makes no publisher,
// subscription, timer or service and no host of the table loads it, so it
// is no node of the graph.
#include "filters/filter_base.hpp"
#include "pluginlib/class_list_macros.hpp"

namespace rsia_ros2_plugins
{

class ScaleFilter : public filters::FilterBase<double>
{
public:
  bool configure() override
  {
    return true;
  }

  bool update(const double & in, double & out) override
  {
    out = 2.0 * in;
    return true;
  }
};

}  // namespace rsia_ros2_plugins

PLUGINLIB_EXPORT_CLASS(rsia_ros2_plugins::ScaleFilter, filters::FilterBase<double>)
