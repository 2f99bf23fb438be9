// Every endpoint is made through rsia_common's wrappers: a heartbeat per
// received pose (a helper object whose beat() publishes), and the relay
// state published from main's 2 Hz Rate loop through a latched publisher
// and through a StatusBoard, whose body is compiled into rsia_common.
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>
#include <rsia_common/status_board.h>
#include <rsia_common/topics.h>
#include <std_msgs/String.h>

class HeartbeatRelay
{
public:
  explicit HeartbeatRelay(ros::NodeHandle& nh) : heartbeat_(nh, "heartbeat"), board_(nh, "relay_board")
  {
    state_pub_ = rsia_common::advertiseLatched<std_msgs::String>(nh, "relay_state");
    pose_sub_ = rsia_common::subscribeTo(nh, "pose", &HeartbeatRelay::onPose, this);
  }

  void publishState()
  {
    std_msgs::String state;
    state.data = received_ > 0 ? "receiving" : "waiting";
    state_pub_.publish(state);
    board_.post(state.data);
  }

private:
  void onPose(const geometry_msgs::PoseStamped::ConstPtr&)
  {
    ++received_;
    heartbeat_.beat();
  }

  int received_ = 0;
  rsia_common::Heartbeat heartbeat_;
  rsia_common::StatusBoard board_;
  ros::Publisher state_pub_;
  ros::Subscriber pose_sub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "heartbeat_relay");
  ros::NodeHandle nh;
  HeartbeatRelay relay(nh);
  ros::Rate rate(2);
  while (ros::ok())
  {
    relay.publishState();
    ros::spinOnce();
    rate.sleep();
  }
  return 0;
}
