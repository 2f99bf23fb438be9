// joint_controller: PD controller for one simulated joint.
//
// RSIA patterns covered here:
// - RATE LOOP IN MAIN in a node that subscribes: the control loop in main is paced by a
//   ros::Rate declared before the loop; its body calls JointController::update(), which
//   publishes directly (RealtimePublisher) and through the helper publishEffort().
//   -> independent, rate_loop.
// - COMPILE-TIME CONSTANT RATE: the Rate is built from `constexpr double kControlRateHz`, so
//   rate_hz of the loop publishers is known (50.0).
// - TIMER: a heartbeat published from a createWallTimer callback -> independent, timer.
// APIs covered: subscribe with boost::bind and with std::bind, advertiseService (member
// function + this), createWallTimer (member callback), ros::Rate loop,
// realtime_tools::RealtimePublisher (stand-in) trylock/msg_/unlockAndPublish,
// diagnostic_updater::Updater add/update.
#include <functional>
#include <string>

#include <boost/bind/bind.hpp>
#include <diagnostic_updater/diagnostic_updater.h>
#include <realtime_tools/realtime_publisher.h>
#include <ros/ros.h>
#include <roscpp/Empty.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Empty.h>
#include <std_msgs/Float64.h>

using namespace boost::placeholders;

// Compile-time constant control rate: the rate_hz of the loop publishers is 50.0.
constexpr double kControlRateHz = 50.0;

class JointController
{
public:
  explicit JointController(ros::NodeHandle& nh)
    // API: realtime_tools::RealtimePublisher, topic = 2nd constructor argument.
    : command_pub_(nh, "joint_command_state", 4)
  {
    ros::NodeHandle pnh("~");
    pnh.param("kp", kp_, 12.0);
    pnh.param("kd", kd_, 0.8);
    pnh.param<std::string>("joint", joint_name_, "joint_0");

    // API: ros::NodeHandle::subscribe with boost::bind (message type given explicitly).
    joint_sub_ = nh.subscribe<sensor_msgs::JointState>(
        "joint_states", 10, boost::bind(&JointController::onJointState, this, _1));
    // API: ros::NodeHandle::subscribe with std::bind.
    setpoint_sub_ = nh.subscribe<std_msgs::Float64>(
        "setpoint", 1, std::bind(&JointController::onSetpoint, this, std::placeholders::_1));

    effort_pub_ = nh.advertise<std_msgs::Float64>("effort", 10);
    heartbeat_pub_ = nh.advertise<std_msgs::Empty>("heartbeat", 1);

    // API: ros::NodeHandle::advertiseService, member function + this.
    hold_srv_ = nh.advertiseService("hold", &JointController::onHold, this);

    // API: ros::NodeHandle::createWallTimer, member callback; 0.5 s -> 2 Hz.
    heartbeat_timer_ =
        nh.createWallTimer(ros::WallDuration(0.5), &JointController::onHeartbeat, this);
  }

  // One control cycle; called only from the Rate loop in main.
  void update(const ros::Duration& dt)
  {
    const double error = setpoint_ - position_;
    const double effort = hold_ ? 0.0 : kp_ * error - kd_ * velocity_;
    publishEffort(effort);

    if (command_pub_.trylock())
    {
      command_pub_.msg_.header.stamp = ros::Time::now();
      command_pub_.msg_.name.assign(1, joint_name_);
      command_pub_.msg_.position.assign(1, setpoint_);
      command_pub_.msg_.effort.assign(1, effort);
      // EXPECT joint_command_state: independent, rate_loop (main's 50 Hz Rate loop ->
      // update()), rate_hz 50.0.
      command_pub_.unlockAndPublish();
    }
    last_cycle_ = dt.toSec();
  }

  // Diagnostic task registered on the Updater in main.
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat)
  {
    if (!received_state_)
    {
      stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no joint_states received");
    }
    else
    {
      stat.summary(diagnostic_msgs::DiagnosticStatus::OK, hold_ ? "holding" : "tracking");
    }
    stat.add("setpoint", setpoint_);
    stat.add("position", position_);
    stat.add("cycle time", last_cycle_);
  }

private:
  // Helper publishing the effort; called from update(), i.e. from the Rate loop body.
  void publishEffort(double effort)
  {
    std_msgs::Float64 msg;
    msg.data = effort;
    // EXPECT effort: independent, rate_loop (main loop -> update() -> publishEffort()),
    // rate_hz 50.0.
    effort_pub_.publish(msg);
  }

  void onJointState(const sensor_msgs::JointState::ConstPtr& msg)
  {
    for (size_t i = 0; i < msg->name.size(); ++i)
    {
      if (msg->name[i] == joint_name_ && i < msg->position.size())
      {
        position_ = msg->position[i];
        velocity_ = i < msg->velocity.size() ? msg->velocity[i] : 0.0;
        received_state_ = true;
      }
    }
  }

  void onSetpoint(const std_msgs::Float64::ConstPtr& msg) { setpoint_ = msg->data; }

  bool onHold(roscpp::Empty::Request& /*req*/, roscpp::Empty::Response& /*res*/)
  {
    hold_ = !hold_;
    return true;
  }

  void onHeartbeat(const ros::WallTimerEvent& /*event*/)
  {
    // EXPECT heartbeat: independent, timer (wall timer callback), rate_hz 2.0.
    heartbeat_pub_.publish(std_msgs::Empty());
  }

  realtime_tools::RealtimePublisher<sensor_msgs::JointState> command_pub_;
  ros::Subscriber joint_sub_;
  ros::Subscriber setpoint_sub_;
  ros::Publisher effort_pub_;
  ros::Publisher heartbeat_pub_;
  ros::ServiceServer hold_srv_;
  ros::WallTimer heartbeat_timer_;

  std::string joint_name_;
  double kp_ = 12.0;
  double kd_ = 0.8;
  double setpoint_ = 0.0;
  double position_ = 0.0;
  double velocity_ = 0.0;
  double last_cycle_ = 0.0;
  bool hold_ = false;
  bool received_state_ = false;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "joint_controller");
  ros::NodeHandle nh;
  JointController controller(nh);

  // API: diagnostic_updater::Updater (implicit publisher /diagnostics).
  diagnostic_updater::Updater updater;
  updater.setHardwareID("sim_joint");
  updater.add("joint controller", &controller, &JointController::diagnose);

  // API: ros::Rate at a compile-time constant rate.
  ros::Rate rate(kControlRateHz);
  ros::Time last = ros::Time::now();
  while (ros::ok())
  {
    ros::spinOnce();
    const ros::Time now = ros::Time::now();
    controller.update(now - last);  // publishes effort and joint_command_state
    last = now;
    // EXPECT /diagnostics: independent, rate_loop (update() runs in the 50 Hz loop),
    // rate_hz 50.0.
    updater.update();
    rate.sleep();
  }
  return 0;
}
