// A filter of a filters::FilterChain: the node that owns the chain loads it.
#include <filters/filter_base.h>
#include <pluginlib/class_list_macros.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Int32.h>

namespace rsia_hosted_plugins
{

class SpikeFilter : public filters::FilterBase<sensor_msgs::LaserScan>
{
public:
  bool configure() override
  {
    ros::NodeHandle nh;
    ros::NodeHandle pnh("~");
    spikes_pub_ = nh.advertise<sensor_msgs::LaserScan>("spikes", 1);
    dropped_pub_ = pnh.advertise<std_msgs::Int32>("dropped", 1);
    alarm_pub_ = nh.advertise<std_msgs::Int32>("/spike_alarm", 1);
    return true;
  }

  bool update(const sensor_msgs::LaserScan& in, sensor_msgs::LaserScan& out) override
  {
    out = in;
    spikes_pub_.publish(in);
    std_msgs::Int32 dropped;
    dropped_pub_.publish(dropped);
    alarm_pub_.publish(dropped);
    return true;
  }

private:
  ros::Publisher spikes_pub_;
  ros::Publisher dropped_pub_;
  ros::Publisher alarm_pub_;
};

}  // namespace rsia_hosted_plugins

PLUGINLIB_EXPORT_CLASS(rsia_hosted_plugins::SpikeFilter, filters::FilterBase<sensor_msgs::LaserScan>)
