// Timers made as objects and added to the node's timers interface, and a
// main that paces rclcpp::spin_some with a WallRate:
// - tick: published by onTick(), which only the GenericTimer's callback
//   calls (100 ms): independent, timer, 10 Hz
// - tock: published by the lambda of the WallTimer made with the class's
//   static make_shared (50 ms): independent, timer, 20 Hz
// - echo: published from the "commands" subscription's callback. main's
//   WallRate(200) loop runs spin_some, but a callback is its own root: the
//   loop paces when callbacks may run, not the callback's input. dependent
#include <chrono>
#include <functional>
#include <memory>
#include <utility>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

class TimerObjects : public rclcpp::Node
{
public:
  TimerObjects()
  : Node("timer_objects")
  {
    tick_pub_ = create_publisher<std_msgs::msg::String>("tick", 10);
    tock_pub_ = create_publisher<std_msgs::msg::String>("tock", 10);
    echo_pub_ = create_publisher<std_msgs::msg::String>("echo", 10);
    commands_sub_ = create_subscription<std_msgs::msg::String>(
      "commands", 10,
      [this](std_msgs::msg::String::ConstSharedPtr msg) {echo_pub_->publish(*msg);});

    auto on_tick = [this]() {onTick();};
    tick_timer_ = std::make_shared<rclcpp::GenericTimer<decltype(on_tick)>>(
      get_clock(), std::chrono::milliseconds(100), std::move(on_tick),
      get_node_base_interface()->get_context());
    get_node_timers_interface()->add_timer(tick_timer_, nullptr);

    tock_timer_ = rclcpp::WallTimer<std::function<void()>>::make_shared(
      std::chrono::milliseconds(50),
      [this]() {tock_pub_->publish(std_msgs::msg::String());},
      get_node_base_interface()->get_context());
    get_node_timers_interface()->add_timer(tock_timer_, nullptr);
  }

private:
  void onTick()
  {
    std_msgs::msg::String msg;
    msg.data = "tick";
    tick_pub_->publish(msg);
  }

  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr tick_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr tock_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr echo_pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr commands_sub_;
  rclcpp::TimerBase::SharedPtr tick_timer_;
  rclcpp::WallTimer<std::function<void()>>::SharedPtr tock_timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<TimerObjects>();
  rclcpp::WallRate rate(200);
  while (rclcpp::ok()) {
    rclcpp::spin_some(node);
    rate.sleep();
  }
  rclcpp::shutdown();
  return 0;
}
