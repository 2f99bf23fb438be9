// The free functions of rclcpp (create_publisher.hpp, create_subscription.hpp,
// create_timer.hpp) instead of the Node methods, as libraries and nodes
// templated on the node type write them.
// - odom_out is republished from the odometry subscription: dependent
// - relay_count comes from a ROS-time timer made with the free
//   rclcpp::create_timer(node, clock, period, callback) (Humble and later)
// - watchdog comes from a timer made with the Jazzy+ clock-first form
//   rclcpp::create_timer(clock, period, callback, group, node_base, node_timers)
// - cmd_vel is subscribed through the node-interfaces form of
//   rclcpp::create_subscription(parameters, topics, topic, qos, callback):
//   the topic is its third argument there
#include <chrono>
#include <functional>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "nav_msgs/msg/odometry.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/int64.hpp"

using namespace std::chrono_literals;
using std::placeholders::_1;

class OdomRelay : public rclcpp::Node
{
public:
  OdomRelay()
  : Node("odom_relay", "robot1")
  {
    odom_pub_ = rclcpp::create_publisher<nav_msgs::msg::Odometry>(
      this, "odom_out", rclcpp::QoS(10));
    count_pub_ = rclcpp::create_publisher<std_msgs::msg::Int64>(
      *this, "relay_count", rclcpp::QoS(1).transient_local());
    watchdog_pub_ = rclcpp::create_publisher<std_msgs::msg::Bool>(
      this, "watchdog", 1);

    odom_sub_ = rclcpp::create_subscription<nav_msgs::msg::Odometry>(
      *this, "odom_in", rclcpp::SensorDataQoS(),
      std::bind(&OdomRelay::onOdom, this, _1));

    auto parameters = get_node_parameters_interface();
    auto topics = get_node_topics_interface();
    cmd_sub_ = rclcpp::create_subscription<geometry_msgs::msg::Twist>(
      parameters, topics, "cmd_vel", 10,
      [this](geometry_msgs::msg::Twist::ConstSharedPtr msg) {
        last_cmd_ = *msg;
        last_cmd_time_ = now();
      });

    count_timer_ = rclcpp::create_timer(
      this, get_clock(), std::chrono::milliseconds(500),
      [this]() {publishCount();});

    watchdog_timer_ = rclcpp::create_timer(
      get_clock(), 200ms, std::bind(&OdomRelay::checkWatchdog, this), nullptr,
      get_node_base_interface().get(), get_node_timers_interface().get());
  }

private:
  void onOdom(const nav_msgs::msg::Odometry::SharedPtr msg)
  {
    ++relayed_;
    odom_pub_->publish(*msg);
  }

  void publishCount()
  {
    std_msgs::msg::Int64 count;
    count.data = relayed_;
    count_pub_->publish(count);
  }

  void checkWatchdog()
  {
    std_msgs::msg::Bool alive;
    alive.data = (now() - last_cmd_time_) < rclcpp::Duration::from_seconds(1.0);
    watchdog_pub_->publish(alive);
  }

  int64_t relayed_ = 0;
  geometry_msgs::msg::Twist last_cmd_;
  rclcpp::Time last_cmd_time_;
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr odom_pub_;
  rclcpp::Publisher<std_msgs::msg::Int64>::SharedPtr count_pub_;
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr watchdog_pub_;
  rclcpp::Subscription<nav_msgs::msg::Odometry>::SharedPtr odom_sub_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr cmd_sub_;
  rclcpp::TimerBase::SharedPtr count_timer_;
  rclcpp::TimerBase::SharedPtr watchdog_timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<OdomRelay>());
  rclcpp::shutdown();
  return 0;
}
