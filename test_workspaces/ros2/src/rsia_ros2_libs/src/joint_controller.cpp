// A joint controller: the 100 Hz control loop is a wall timer; it publishes
// the joint state through a realtime_tools::RealtimePublisher that wraps an
// rclcpp publisher (trylock / msg_ / unlockAndPublish). Commands arrive on a
// subscription, whose callback acknowledges them through a second wrapper
// with the Jazzy try_publish.
#include <chrono>
#include <functional>
#include <memory>
#include <vector>

#include "rclcpp/rclcpp.hpp"
#include "realtime_tools/realtime_publisher.h"
#include "sensor_msgs/msg/joint_state.hpp"
#include "std_msgs/msg/float64_multi_array.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

class JointController : public rclcpp::Node
{
public:
  JointController()
  : Node("joint_controller")
  {
    state_pub_ = create_publisher<sensor_msgs::msg::JointState>(
      "joint_states_rt", rclcpp::SystemDefaultsQoS());
    rt_state_pub_ =
      std::make_unique<realtime_tools::RealtimePublisher<sensor_msgs::msg::JointState>>(
      state_pub_);
    ack_pub_ = create_publisher<std_msgs::msg::String>("command_ack", 10);
    rt_ack_pub_ =
      std::make_shared<realtime_tools::RealtimePublisher<std_msgs::msg::String>>(ack_pub_);
    command_sub_ = create_subscription<std_msgs::msg::Float64MultiArray>(
      "joint_commands", 10,
      std::bind(&JointController::onCommand, this, std::placeholders::_1));
    control_timer_ = create_wall_timer(10ms, std::bind(&JointController::update, this));
  }

private:
  void update()
  {
    for (size_t i = 0; i < positions_.size(); ++i) {
      positions_[i] += 0.01 * (command_[i] - positions_[i]);
    }
    if (rt_state_pub_->trylock()) {
      rt_state_pub_->msg_.header.stamp = now();
      rt_state_pub_->msg_.position = positions_;
      rt_state_pub_->unlockAndPublish();
    }
  }

  void onCommand(const std_msgs::msg::Float64MultiArray::SharedPtr msg)
  {
    command_ = msg->data;
    std_msgs::msg::String ack;
    ack.data = "accepted";
    rt_ack_pub_->try_publish(ack);
  }

  std::vector<double> positions_ = std::vector<double>(6, 0.0);
  std::vector<double> command_ = std::vector<double>(6, 0.0);
  rclcpp::Publisher<sensor_msgs::msg::JointState>::SharedPtr state_pub_;
  std::unique_ptr<realtime_tools::RealtimePublisher<sensor_msgs::msg::JointState>>
  rt_state_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr ack_pub_;
  std::shared_ptr<realtime_tools::RealtimePublisher<std_msgs::msg::String>> rt_ack_pub_;
  rclcpp::Subscription<std_msgs::msg::Float64MultiArray>::SharedPtr command_sub_;
  rclcpp::TimerBase::SharedPtr control_timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<JointController>());
  rclcpp::shutdown();
  return 0;
}
