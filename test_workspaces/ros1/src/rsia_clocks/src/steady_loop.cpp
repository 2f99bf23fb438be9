// Loops paced by the standard library's clocks. Only a loop that sleeps
// until a deadline it advances by a fixed period runs at a fixed rate.
#include <chrono>
#include <thread>

#include <ros/ros.h>
#include <std_msgs/Float64.h>

static constexpr auto kSetpointPeriod = std::chrono::milliseconds(40);  // 25 Hz

static double g_gain = 1.0;

static void onGain(const std_msgs::Float64::ConstPtr & msg)
{
  g_gain = msg->data;
}

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "steady_loop");
  ros::NodeHandle nh;
  ros::Publisher setpoint_pub = nh.advertise<std_msgs::Float64>("setpoint", 10);
  ros::Publisher drift_pub = nh.advertise<std_msgs::Float64>("drift", 10);
  ros::Publisher late_pub = nh.advertise<std_msgs::Float64>("late", 10);
  ros::Subscriber gain_sub = nh.subscribe("gain", 1, onGain);
  ros::AsyncSpinner spinner(1);
  spinner.start();

  // sleeps a fixed time after the work: the period drifts with the work
  std::thread drifting([&drift_pub]() {
      while (ros::ok()) {
        std_msgs::Float64 value;
        value.data = g_gain;
        drift_pub.publish(value);
        std::this_thread::sleep_for(std::chrono::milliseconds(40));
      }
    });

  // the deadline never moves: after the first pass the loop does not sleep
  std::thread late([&late_pub]() {
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
      while (ros::ok()) {
        late_pub.publish(std_msgs::Float64());
        std::this_thread::sleep_until(deadline);
      }
    });

  auto next = std::chrono::steady_clock::now();
  while (ros::ok()) {
    next += kSetpointPeriod;
    std_msgs::Float64 setpoint;
    setpoint.data = g_gain;
    setpoint_pub.publish(setpoint);
    std::this_thread::sleep_until(next);
  }
  drifting.join();
  late.join();
  return 0;
}
