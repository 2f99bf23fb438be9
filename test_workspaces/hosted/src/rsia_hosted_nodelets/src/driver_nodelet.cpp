#include <boost/thread.hpp>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <rsia_hosted_nodelets/driver.h>

namespace rsia_hosted_nodelets
{

class DriverNodelet : public nodelet::Nodelet
{
  void onInit() override
  {
    driver_.reset(new Driver(getNodeHandle(), getPrivateNodeHandle()));
    thread_.reset(new boost::thread(boost::bind(&DriverNodelet::run, this)));
  }

  void run()
  {
    while (ros::ok() && driver_->poll())
    {
    }
  }

  boost::shared_ptr<Driver> driver_;
  boost::shared_ptr<boost::thread> thread_;
};

}  // namespace rsia_hosted_nodelets

PLUGINLIB_EXPORT_CLASS(rsia_hosted_nodelets::DriverNodelet, nodelet::Nodelet)
