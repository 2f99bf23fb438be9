// A sub-node: create_sub_node("arm") extends the namespace of what is made
// through it, so joint_states resolves to /robot/arm/joint_states (the
// summary keeps topics as written: joint_states, gripper/position, command).
// - joint_states from the 50 Hz wall timer: independent
// - gripper/position from the trajectory callback: dependent
#include <chrono>
#include <functional>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/joint_state.hpp"
#include "std_msgs/msg/float64.hpp"
#include "trajectory_msgs/msg/joint_trajectory.hpp"

class ArmDriver : public rclcpp::Node
{
public:
  ArmDriver()
  : Node("arm_driver", "robot")
  {
    arm_ = create_sub_node("arm");
    joint_pub_ = arm_->create_publisher<sensor_msgs::msg::JointState>(
      "joint_states", 10);
    gripper_pub_ = arm_->create_publisher<std_msgs::msg::Float64>(
      "gripper/position", 10);
    command_sub_ = arm_->create_subscription<trajectory_msgs::msg::JointTrajectory>(
      "command", 10, std::bind(&ArmDriver::onCommand, this, std::placeholders::_1));
    timer_ = create_wall_timer(
      std::chrono::milliseconds(20), [this]() {publishJoints();});
  }

private:
  void publishJoints()
  {
    sensor_msgs::msg::JointState state;
    state.header.stamp = now();
    state.name = {"shoulder", "elbow", "wrist"};
    joint_pub_->publish(state);
  }

  void onCommand(const trajectory_msgs::msg::JointTrajectory & trajectory)
  {
    std_msgs::msg::Float64 gripper;
    gripper.data = trajectory.points.empty() ? 0.0 : 1.0;
    gripper_pub_->publish(gripper);
  }

  rclcpp::Node::SharedPtr arm_;
  rclcpp::Publisher<sensor_msgs::msg::JointState>::SharedPtr joint_pub_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr gripper_pub_;
  rclcpp::Subscription<trajectory_msgs::msg::JointTrajectory>::SharedPtr command_sub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ArmDriver>());
  rclcpp::shutdown();
  return 0;
}
