// mission_client: sends trajectory goals leg after leg while the battery lasts.
//
// RSIA patterns covered here:
// - A ros::Rate IS declared in main, but it only paces the wait-for-server loop. The
//   publishing loop after it never calls wait_rate.sleep(): each iteration lasts as long as
//   the action takes -> dependent.
// - actionlib::SimpleActionClient (an action CLIENT is not a subscriber for pattern 1; the
//   node subscribes to `battery` anyway); a service client (no topic, no input either).
#include <actionlib/TestAction.h>
#include <actionlib/client/simple_action_client.h>
#include <ros/ros.h>
#include <roscpp/Empty.h>
#include <sensor_msgs/BatteryState.h>
#include <std_msgs/Int32.h>

namespace
{
double g_battery = 1.0;  // state of charge, 0..1
}  // namespace

// Subscriber callback (free function).
void onBattery(const sensor_msgs::BatteryState::ConstPtr& msg)
{
  g_battery = msg->percentage;
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "mission_client");
  ros::NodeHandle nh;

  ros::Subscriber battery_sub = nh.subscribe("battery", 1, onBattery);
  ros::Publisher leg_pub = nh.advertise<std_msgs::Int32>("mission_leg", 1);
  // API: ros::NodeHandle::serviceClient, called when the mission ends.
  ros::ServiceClient reset_client = nh.serviceClient<roscpp::Empty>("reset_mission");

  // API: actionlib::SimpleActionClient (name, spin_thread).
  actionlib::SimpleActionClient<actionlib::TestAction> client("execute_trajectory", true);

  // API: ros::topic::waitForMessage: a one-shot subscription (an input like any other).
  sensor_msgs::BatteryState::ConstPtr first_state =
      ros::topic::waitForMessage<sensor_msgs::BatteryState>("battery", nh, ros::Duration(10.0));
  if (first_state)
  {
    g_battery = first_state->percentage;
  }

  // This Rate paces only the waiting loop below...
  ros::Rate wait_rate(2.0);
  while (ros::ok() && !client.isServerConnected())
  {
    ROS_INFO_THROTTLE(5.0, "mission_client: waiting for execute_trajectory");
    ros::spinOnce();
    wait_rate.sleep();
  }

  int leg = 0;
  // ...and NOT this publishing loop: it is paced by the action's duration.
  while (ros::ok() && g_battery > 0.2)
  {
    ros::spinOnce();
    actionlib::TestGoal goal;
    goal.goal = 5 + leg % 3;
    client.sendGoal(goal);
    if (!client.waitForResult(ros::Duration(30.0)))
    {
      client.cancelGoal();
    }
    std_msgs::Int32 msg;
    msg.data = ++leg;
    // EXPECT mission_leg: dependent, none (wait_rate is declared in this function but does
    // not pace this loop; no timer or Rate-paced loop on the path).
    leg_pub.publish(msg);
  }
  roscpp::Empty reset;
  reset_client.call(reset);
  return 0;
}
