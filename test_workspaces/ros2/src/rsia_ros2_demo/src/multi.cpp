// two nodes in one executable: a lifecycle node publishing from a 5 Hz wall
// timer (a std::chrono::duration<double> period) and a plain node with a
// service whose callback is a std::function member
#include <chrono>
#include <functional>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"
#include "std_msgs/msg/string.hpp"
#include "std_srvs/srv/trigger.hpp"

using CallbackReturn =
  rclcpp_lifecycle::node_interfaces::LifecycleNodeInterface::CallbackReturn;

class Lifecycle : public rclcpp_lifecycle::LifecycleNode
{
public:
  Lifecycle()
  : LifecycleNode("lifecycle") {}

  CallbackReturn on_configure(const rclcpp_lifecycle::State &) override
  {
    pub_ = create_publisher<std_msgs::msg::String>("lc_out", 10);
    timer_ = create_wall_timer(
      std::chrono::duration<double>(0.2), [this]() {tick();});
    return CallbackReturn::SUCCESS;
  }

private:
  void tick()
  {
    std_msgs::msg::String msg;
    pub_->publish(msg);
  }

  rclcpp_lifecycle::LifecyclePublisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

class Server : public rclcpp::Node
{
public:
  Server()
  : Node("server")
  {
    handler_ = std::bind(
      &Server::onTrigger, this, std::placeholders::_1, std::placeholders::_2);
    service_ = create_service<std_srvs::srv::Trigger>("trigger", handler_);
  }

private:
  void onTrigger(
    const std::shared_ptr<std_srvs::srv::Trigger::Request> request,
    std::shared_ptr<std_srvs::srv::Trigger::Response> response)
  {
    (void)request;
    (void)response;
  }

  std::function<void(
      const std::shared_ptr<std_srvs::srv::Trigger::Request>,
      std::shared_ptr<std_srvs::srv::Trigger::Response>)> handler_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr service_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::executors::SingleThreadedExecutor executor;
  auto lifecycle = std::make_shared<Lifecycle>();
  auto server = std::make_shared<Server>();
  executor.add_node(lifecycle->get_node_base_interface());
  executor.add_node(server);
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
