// A world plugin publishing from its world-update handler through a
// NodeHandle in gzserver's own namespace.
#include <boost/bind.hpp>
#include <gazebo/common/Plugin.hh>
#include <gazebo/physics/World.hh>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>

namespace rsia_gazebo_plugins
{

class TickPlugin : public gazebo::WorldPlugin
{
public:
  void Load(gazebo::physics::WorldPtr world, sdf::ElementPtr sdf) override
  {
    tick_pub_ = nh_.advertise<rosgraph_msgs::Clock>("sim_tick", 10);
    connection_ = gazebo::event::Events::ConnectWorldUpdateBegin(
      boost::bind(&TickPlugin::OnWorldUpdate, this, _1));
  }

  void OnWorldUpdate(const gazebo::common::UpdateInfo& info)
  {
    rosgraph_msgs::Clock tick;
    tick_pub_.publish(tick);
  }

private:
  ros::NodeHandle nh_;
  ros::Publisher tick_pub_;
  gazebo::event::ConnectionPtr connection_;
};

GZ_REGISTER_WORLD_PLUGIN(TickPlugin)

}  // namespace rsia_gazebo_plugins
