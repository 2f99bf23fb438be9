// Every endpoint is made through rsia_ros2_common: the relay publisher and
// the command subscription by the free wrappers, a status publisher by a
// helper object, and a debug topic by a publish-on-first-use helper called
// from a 4 Hz timer. GraphListener and make_gauge are compiled into
// rsia_ros2_common's library: only their declarations are seen here.
#include <chrono>
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"
#include "rsia_ros2_common/endpoints.hpp"
#include "rsia_ros2_common/graph_listener.hpp"
#include "std_msgs/msg/float64.hpp"

using namespace std::chrono_literals;

class VelocityRelay : public rclcpp::Node
{
public:
  VelocityRelay()
  : Node("velocity_relay"),
    status_(this, "relay_status"),
    debug_(this),
    graph_(this)
  {
    graph_.subscribe(this, 5);
    gauge_pub_ = rsia_ros2_common::make_gauge(this, "relay_gauge");
    relay_pub_ = rsia_ros2_common::make_publisher<geometry_msgs::msg::Twist>(
      this, "cmd_vel_out");
    command_sub_ = rsia_ros2_common::make_subscription<geometry_msgs::msg::Twist>(
      this, "cmd_vel_in",
      [this](const geometry_msgs::msg::Twist::SharedPtr msg) {
        relay_pub_->publish(*msg);
        status_.report("relayed");
        ++relayed_;
      });
    timer_ = create_wall_timer(250ms, [this]() {onTimer();});
    mode_pub_ = rsia_ros2_common::make_mode_publisher(this);
  }

private:
  void onTimer()
  {
    std_msgs::msg::Float64 count;
    count.data = relayed_;
    debug_.publish<std_msgs::msg::Float64>("debug/relayed", count);
    std_msgs::msg::String mode;
    mode.data = "relay";
    mode_pub_->publish(mode);
    graph_.announce("tick");
    gauge_pub_->publish(count);
  }

  int relayed_ = 0;
  rsia_ros2_common::StatusReporter status_;
  rsia_ros2_common::DebugPublisher debug_;
  rsia_ros2_common::GraphListener graph_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr gauge_pub_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr relay_pub_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr command_sub_;
  rclcpp::TimerBase::SharedPtr timer_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr mode_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<VelocityRelay>());
  rclcpp::shutdown();
  return 0;
}
