// The Fibonacci action server of the ROS 2 tutorials, plus two topics: the
// goal callback counts accepted goals on goals_received, and the execute
// thread (started from handle_accepted) publishes feedback and a progress
// topic inside a 1 Hz rclcpp::Rate loop.
#include <functional>
#include <memory>
#include <thread>

#include "example_interfaces/action/fibonacci.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "std_msgs/msg/float32.hpp"
#include "std_msgs/msg/int32.hpp"

class FibonacciServer : public rclcpp::Node
{
public:
  using Fibonacci = example_interfaces::action::Fibonacci;
  using GoalHandleFibonacci = rclcpp_action::ServerGoalHandle<Fibonacci>;

  FibonacciServer()
  : Node("fibonacci_server")
  {
    using namespace std::placeholders;
    goals_pub_ = create_publisher<std_msgs::msg::Int32>("goals_received", 10);
    progress_pub_ = create_publisher<std_msgs::msg::Float32>("fibonacci_progress", 10);
    action_server_ = rclcpp_action::create_server<Fibonacci>(
      this, "fibonacci",
      std::bind(&FibonacciServer::handle_goal, this, _1, _2),
      [](const std::shared_ptr<GoalHandleFibonacci>) {
        return rclcpp_action::CancelResponse::ACCEPT;
      },
      std::bind(&FibonacciServer::handle_accepted, this, _1));
  }

private:
  rclcpp_action::GoalResponse handle_goal(
    const rclcpp_action::GoalUUID & uuid,
    std::shared_ptr<const Fibonacci::Goal> goal)
  {
    (void)uuid;
    if (goal->order > 46) {
      return rclcpp_action::GoalResponse::REJECT;
    }
    std_msgs::msg::Int32 count;
    count.data = ++goals_;
    goals_pub_->publish(count);
    return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
  }

  void handle_accepted(const std::shared_ptr<GoalHandleFibonacci> goal_handle)
  {
    using namespace std::placeholders;
    std::thread{std::bind(&FibonacciServer::execute, this, _1), goal_handle}.detach();
  }

  void execute(const std::shared_ptr<GoalHandleFibonacci> goal_handle)
  {
    rclcpp::Rate loop_rate(1);
    const auto goal = goal_handle->get_goal();
    auto feedback = std::make_shared<Fibonacci::Feedback>();
    auto & sequence = feedback->sequence;
    sequence.push_back(0);
    sequence.push_back(1);
    auto result = std::make_shared<Fibonacci::Result>();
    for (int i = 1; (i < goal->order) && rclcpp::ok(); ++i) {
      if (goal_handle->is_canceling()) {
        result->sequence = sequence;
        goal_handle->canceled(result);
        return;
      }
      sequence.push_back(sequence[i] + sequence[i - 1]);
      goal_handle->publish_feedback(feedback);
      std_msgs::msg::Float32 progress;
      progress.data = static_cast<float>(i) / goal->order;
      progress_pub_->publish(progress);
      loop_rate.sleep();
    }
    if (rclcpp::ok()) {
      result->sequence = sequence;
      goal_handle->succeed(result);
    }
  }

  int goals_{0};
  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr goals_pub_;
  rclcpp::Publisher<std_msgs::msg::Float32>::SharedPtr progress_pub_;
  rclcpp_action::Server<Fibonacci>::SharedPtr action_server_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<FibonacciServer>());
  rclcpp::shutdown();
  return 0;
}
