// The Fibonacci action client of the ROS 2 tutorials: a 500 ms timer sends a
// goal (with goal-response, feedback and result callbacks in
// SendGoalOptions) and counts the goals sent on goals_sent.
#include <chrono>
#include <functional>
#include <memory>

#include "example_interfaces/action/fibonacci.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "std_msgs/msg/int32.hpp"

using namespace std::chrono_literals;

class FibonacciClient : public rclcpp::Node
{
public:
  using Fibonacci = example_interfaces::action::Fibonacci;
  using GoalHandleFibonacci = rclcpp_action::ClientGoalHandle<Fibonacci>;

  FibonacciClient()
  : Node("fibonacci_client")
  {
    client_ = rclcpp_action::create_client<Fibonacci>(this, "fibonacci");
    sent_pub_ = create_publisher<std_msgs::msg::Int32>("goals_sent", 10);
    timer_ = create_wall_timer(500ms, std::bind(&FibonacciClient::send_goal, this));
  }

private:
  void send_goal()
  {
    using namespace std::placeholders;
    if (!client_->wait_for_action_server(std::chrono::seconds(1))) {
      RCLCPP_ERROR(get_logger(), "action server not available");
      return;
    }
    auto goal = Fibonacci::Goal();
    goal.order = 10;
    auto options = rclcpp_action::Client<Fibonacci>::SendGoalOptions();
    options.goal_response_callback =
      std::bind(&FibonacciClient::goal_response_callback, this, _1);
    options.feedback_callback =
      std::bind(&FibonacciClient::feedback_callback, this, _1, _2);
    options.result_callback =
      std::bind(&FibonacciClient::result_callback, this, _1);
    client_->async_send_goal(goal, options);
    std_msgs::msg::Int32 sent;
    sent.data = ++sent_;
    sent_pub_->publish(sent);
  }

  void goal_response_callback(const GoalHandleFibonacci::SharedPtr & goal_handle)
  {
    if (!goal_handle) {
      RCLCPP_ERROR(get_logger(), "goal was rejected");
    }
  }

  void feedback_callback(
    GoalHandleFibonacci::SharedPtr,
    const std::shared_ptr<const Fibonacci::Feedback> feedback)
  {
    RCLCPP_INFO(get_logger(), "next number: %d", feedback->sequence.back());
  }

  void result_callback(const GoalHandleFibonacci::WrappedResult & result)
  {
    if (result.code == rclcpp_action::ResultCode::SUCCEEDED) {
      RCLCPP_INFO(get_logger(), "done");
    }
  }

  int sent_{0};
  rclcpp_action::Client<Fibonacci>::SharedPtr client_;
  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr sent_pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<FibonacciClient>());
  rclcpp::shutdown();
  return 0;
}
