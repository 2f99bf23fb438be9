// Merges two streams: whatever arrives on `in_a` or `in_b` is forwarded to
// `merged` from the subscriber callbacks (dependent on both input rates).
#include <ros/ros.h>
#include <std_msgs/Header.h>

class Merger
{
public:
  explicit Merger(ros::NodeHandle& nh)
  {
    merged_pub_ = nh.advertise<std_msgs::Header>("merged", 10);
    sub_a_ = nh.subscribe("in_a", 10, &Merger::onA, this);
    sub_b_ = nh.subscribe("in_b", 10, &Merger::onB, this);
  }

private:
  void onA(const std_msgs::Header::ConstPtr& msg) { forward(*msg, "a"); }
  void onB(const std_msgs::Header::ConstPtr& msg) { forward(*msg, "b"); }

  void forward(const std_msgs::Header& in, const char* source)
  {
    std_msgs::Header out = in;
    out.frame_id = source;
    merged_pub_.publish(out);
  }

  ros::Publisher merged_pub_;
  ros::Subscriber sub_a_;
  ros::Subscriber sub_b_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "merger");
  ros::NodeHandle nh;
  Merger merger(nh);
  ros::spin();
  return 0;
}
