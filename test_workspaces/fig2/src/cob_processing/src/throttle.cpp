// Keeps the latest message of `input` and republishes it on `output` from a
// 5 Hz timer: the output rate is fixed by the timer (independent, timer).
#include <ros/ros.h>
#include <std_msgs/Header.h>

class Throttle
{
public:
  explicit Throttle(ros::NodeHandle& nh)
  {
    output_pub_ = nh.advertise<std_msgs::Header>("output", 1);
    input_sub_ = nh.subscribe("input", 1, &Throttle::onInput, this);
    timer_ = nh.createTimer(ros::Duration(0.2), &Throttle::onTimer, this);
  }

private:
  void onInput(const std_msgs::Header::ConstPtr& msg)
  {
    latest_ = *msg;
    have_msg_ = true;
  }

  void onTimer(const ros::TimerEvent&)
  {
    if (have_msg_)
      output_pub_.publish(latest_);
  }

  ros::Publisher output_pub_;
  ros::Subscriber input_sub_;
  ros::Timer timer_;
  std_msgs::Header latest_;
  bool have_msg_ = false;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "throttle");
  ros::NodeHandle nh;
  Throttle throttle(nh);
  ros::spin();
  return 0;
}
