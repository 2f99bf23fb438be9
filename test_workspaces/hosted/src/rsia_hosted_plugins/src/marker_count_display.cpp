// An rviz display: rviz loads it into its own process.
#include <pluginlib/class_list_macros.h>
#include <ros/ros.h>
#include <rviz/display.h>
#include <std_msgs/Int32.h>

namespace rsia_hosted_plugins
{

class MarkerCountDisplay : public rviz::Display
{
protected:
  void onInitialize() override
  {
    count_pub_ = nh_.advertise<std_msgs::Int32>("marker_count", 1);
  }

  void update(float wall_dt, float ros_dt) override
  {
    std_msgs::Int32 count;
    count_pub_.publish(count);
  }

private:
  ros::NodeHandle nh_;
  ros::Publisher count_pub_;
};

}  // namespace rsia_hosted_plugins

PLUGINLIB_EXPORT_CLASS(rsia_hosted_plugins::MarkerCountDisplay, rviz::Display)
