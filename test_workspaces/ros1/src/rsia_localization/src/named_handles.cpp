// named_handles: NodeHandles whose namespaces are values, as turtlesim's
// `ros::NodeHandle nh(real_name)` is.
// EXPECT: `pose` is advertised on a handle in `real_name`, a string set once
// to "turtle1": /turtle1/pose, published from a 2 Hz Rate loop. The Turtle's
// handle is in the namespace its constructor is given, a command-line
// argument here: `cmd` and `status` are relative to a namespace the analysis
// cannot know, so they stay unresolved (with a note), never taken for /cmd
// and /status. `status` is published from the `cmd` callback (dependent).
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

class Turtle
{
public:
  Turtle(const ros::NodeHandle& parent, const std::string& name) : nh_(parent, name)
  {
    cmd_sub_ = nh_.subscribe("cmd", 1, &Turtle::onCommand, this);
    status_pub_ = nh_.advertise<std_msgs::String>("status", 1);
  }

private:
  void onCommand(const std_msgs::String::ConstPtr& msg)
  {
    status_pub_.publish(*msg);
  }

  ros::NodeHandle nh_;
  ros::Subscriber cmd_sub_;
  ros::Publisher status_pub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "named_handles");
  std::string real_name = "turtle1";
  ros::NodeHandle nh(real_name);
  ros::Publisher pose_pub = nh.advertise<std_msgs::String>("pose", 1);

  ros::NodeHandle root;
  Turtle turtle(root, argc > 1 ? argv[1] : "turtle2");

  ros::Rate rate(2);
  while (ros::ok())
  {
    pose_pub.publish(std_msgs::String());
    ros::spinOnce();
    rate.sleep();
  }
  return 0;
}
