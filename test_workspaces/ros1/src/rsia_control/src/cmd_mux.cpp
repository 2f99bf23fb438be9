// cmd_mux: forwards the teleop velocity command while it is fresh, else the navigation one.
//
// RSIA patterns covered here:
// - LOOP PACED BY ros::Duration::sleep() in a node that subscribes. A fixed Duration sleep is
//   not adaptive (the period stretches with the work done and with the callbacks handled by
//   spinOnce), so the loop does not count as a rate loop -> dependent.
// - LAMBDA subscriber callbacks passed to subscribe<Msg>(...) (bound to its boost::function
//   parameter); a publish inside a lambda subscriber callback -> dependent.
#include <string>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "cmd_mux");
  ros::NodeHandle nh;

  geometry_msgs::Twist teleop_cmd;
  geometry_msgs::Twist nav_cmd;
  ros::Time teleop_stamp;
  ros::Time nav_stamp;
  std::string active = "none";

  ros::Publisher cmd_pub = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  ros::Publisher active_pub = nh.advertise<std_msgs::String>("mux_active", 1);

  // API: ros::NodeHandle::subscribe<Msg> with a lambda (boost::function parameter).
  ros::Subscriber teleop_sub = nh.subscribe<geometry_msgs::Twist>(
      "teleop/cmd_vel", 1,
      [&](const geometry_msgs::Twist::ConstPtr& msg) {
        teleop_cmd = *msg;
        teleop_stamp = ros::Time::now();
        if (active != "teleop")
        {
          active = "teleop";
          std_msgs::String note;
          note.data = active;
          // EXPECT mux_active: dependent, none (lambda subscriber callback).
          active_pub.publish(note);
        }
      });
  ros::Subscriber nav_sub = nh.subscribe<geometry_msgs::Twist>(
      "nav/cmd_vel", 1,
      [&](const geometry_msgs::Twist::ConstPtr& msg) {
        nav_cmd = *msg;
        nav_stamp = ros::Time::now();
      });

  const ros::Duration timeout(0.5);
  while (ros::ok())
  {
    ros::spinOnce();
    const ros::Time now = ros::Time::now();
    geometry_msgs::Twist out;  // all zero: stop when no source is fresh
    if (now - teleop_stamp < timeout)
    {
      out = teleop_cmd;
    }
    else if (now - nav_stamp < timeout)
    {
      out = nav_cmd;
    }
    // EXPECT cmd_vel: dependent, none (loop paced by ros::Duration::sleep, not by a
    // ros::Rate: main without a Rate-paced loop).
    cmd_pub.publish(out);
    ros::Duration(0.05).sleep();
  }
  return 0;
}
