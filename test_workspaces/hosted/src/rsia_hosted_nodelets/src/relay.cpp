#include <pluginlib/class_list_macros.h>
#include <rsia_hosted_nodelets/relay_base.h>
#include <std_msgs/String.h>

namespace rsia_hosted_nodelets
{

class Relay : public RelayBase
{
protected:
  void onInit() override
  {
    RelayBase::onInit();
    output_pub_ = pnh_->advertise<std_msgs::String>("output", 1);
    input_sub_ = pnh_->subscribe("input", 1, &Relay::onInput, this);
  }

  void onInput(const std_msgs::String::ConstPtr& text)
  {
    output_pub_.publish(*text);
  }

  ros::Publisher output_pub_;
  ros::Subscriber input_sub_;
};

}  // namespace rsia_hosted_nodelets

// exported under a short name, as the plugin XML gives it
typedef rsia_hosted_nodelets::Relay Relay;
PLUGINLIB_EXPORT_CLASS(Relay, nodelet::Nodelet)
