// A lazy relay: it subscribes to its input only while its output has
// subscribers (the subscription is made in the publisher's connect
// callback), and forwards every scan from the subscription's callback.
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <boost/bind/bind.hpp>

class LazyRelay
{
public:
  explicit LazyRelay(ros::NodeHandle & nh)
  : nh_(nh)
  {
    ros::SubscriberStatusCallback status =
      boost::bind(&LazyRelay::onConnection, this);
    pub_ = nh.advertise<sensor_msgs::LaserScan>("scan_lazy", 10, status, status);
  }

private:
  void onConnection()
  {
    if (pub_.getNumSubscribers() == 0) {
      sub_.shutdown();
    } else if (!sub_) {
      sub_ = nh_.subscribe("scan", 10, &LazyRelay::onScan, this);
    }
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr & scan)
  {
    pub_.publish(*scan);
  }

  ros::NodeHandle nh_;
  ros::Publisher pub_;
  ros::Subscriber sub_;
};

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "lazy_relay");
  ros::NodeHandle nh;
  LazyRelay relay(nh);
  ros::spin();
  return 0;
}
