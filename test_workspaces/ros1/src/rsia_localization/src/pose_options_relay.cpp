// pose_options_relay: subscribes and advertises through option objects, as
// code that sets transport hints or callback queues does:
// ros::SubscribeOptions::create<M>(topic, queue, callback, ...) passed to
// subscribe(ops), and ros::AdvertiseOptions::init<M>(topic, queue) passed to
// advertise(ops). Each pose received is relayed.
// EXPECT: subscriber `pose` (geometry_msgs::PoseStamped, callback onPose);
// publisher `pose_relayed` dependent (published in the subscription callback).
#include <ros/ros.h>
#include <geometry_msgs/PoseStamped.h>

ros::Publisher relay_pub;

void onPose(const geometry_msgs::PoseStamped::ConstPtr& msg)
{
  relay_pub.publish(*msg);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "pose_options_relay");
  ros::NodeHandle nh;

  ros::AdvertiseOptions advertise_ops;
  advertise_ops.init<geometry_msgs::PoseStamped>("pose_relayed", 5);
  relay_pub = nh.advertise(advertise_ops);

  ros::SubscribeOptions subscribe_ops = ros::SubscribeOptions::create<geometry_msgs::PoseStamped>(
      "pose", 5, onPose, ros::VoidPtr(), nullptr);
  ros::Subscriber sub = nh.subscribe(subscribe_ops);

  ros::spin();
  return 0;
}
