// Counts ticks. Built twice: as the `counter` executable and, with
// RSIA_COUNTER_NODELET defined, as the nodelet rsia_hosted_nodelets/counter.
#include <ros/ros.h>
#include <std_msgs/Int32.h>

#ifdef RSIA_COUNTER_NODELET
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#endif

namespace rsia_hosted_nodelets
{

class Counter
{
public:
  Counter(ros::NodeHandle nh, ros::NodeHandle pnh)
  {
    count_pub_ = pnh.advertise<std_msgs::Int32>("count", 10);
    tick_sub_ = nh.subscribe("ticks", 10, &Counter::onTick, this);
  }

  void onTick(const std_msgs::Int32::ConstPtr& tick)
  {
    std_msgs::Int32 count;
    count.data = ++count_ + tick->data * 0;
    count_pub_.publish(count);
  }

private:
  ros::Publisher count_pub_;
  ros::Subscriber tick_sub_;
  int count_ = 0;
};

#ifdef RSIA_COUNTER_NODELET
class CounterNodelet : public nodelet::Nodelet
{
  void onInit() override
  {
    counter_.reset(new Counter(getNodeHandle(), getPrivateNodeHandle()));
  }

  boost::shared_ptr<Counter> counter_;
};
#endif

}  // namespace rsia_hosted_nodelets

#ifdef RSIA_COUNTER_NODELET
PLUGINLIB_EXPORT_CLASS(rsia_hosted_nodelets::CounterNodelet, nodelet::Nodelet)
#else
int main(int argc, char** argv)
{
  ros::init(argc, argv, "counter");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  rsia_hosted_nodelets::Counter counter(nh, pnh);
  ros::spin();
  return 0;
}
#endif
