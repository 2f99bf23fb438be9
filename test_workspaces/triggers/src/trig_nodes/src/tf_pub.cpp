// tf_pub: broadcasts /tf from a 50 Hz timer (the tf hub).
// EXPECT rate /tf: 50 Hz (timer).
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

class TfPublisher
{
public:
  explicit TfPublisher(ros::NodeHandle& nh)
  {
    timer_ = nh.createTimer(ros::Duration(0.02), &TfPublisher::onTimer, this);
  }

  void onTimer(const ros::TimerEvent&)
  {
    geometry_msgs::TransformStamped transform;
    transform.header.stamp = ros::Time::now();
    transform.header.frame_id = "odom";
    transform.child_frame_id = "base_link";
    transform.transform.rotation.w = 1.0;
    broadcaster_.sendTransform(transform);
  }

private:
  tf2_ros::TransformBroadcaster broadcaster_;
  ros::Timer timer_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "tf_pub");
  ros::NodeHandle nh;
  TfPublisher node(nh);
  ros::spin();
  return 0;
}
