// A node named through its classes: main makes
// std::make_shared<SonarNode>("front_sonar"); SonarNode hands the name to
// SensorNode(const std::string & name), which hands it on to rclcpp::Node.
// The base class's private ~/status therefore resolves to
// /front_sonar/status.
// - range and ~/status are published only from the 100 ms timer (status
//   through the base class's publishStatus): independent (timer, 10 Hz)
// - the node subscribes to sonar_enable, so pattern 1 does not apply
// - the range topic is a string member set only by its initializer: "range"
// - ping is published only from a rclcpp::WallTimer made directly (250 ms)
//   and added to the node's timers interface: independent (timer, 4 Hz)
#include <chrono>
#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/range.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/empty.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

class SensorNode : public rclcpp::Node
{
public:
  explicit SensorNode(const std::string & name)
  : Node(name)
  {
    status_pub_ = create_publisher<std_msgs::msg::String>("~/status", 1);
  }

protected:
  void publishStatus(const std::string & text)
  {
    std_msgs::msg::String status;
    status.data = text;
    status_pub_->publish(status);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
};

class SonarNode : public SensorNode
{
public:
  explicit SonarNode(const std::string & name)
  : SensorNode(name)
  {
    range_pub_ = create_publisher<sensor_msgs::msg::Range>(range_topic_, 10);
    enable_sub_ = create_subscription<std_msgs::msg::Bool>(
      "sonar_enable", 1,
      [this](const std_msgs::msg::Bool & msg) {enabled_ = msg.data;});
    timer_ = create_wall_timer(100ms, std::bind(&SonarNode::onTimer, this));

    ping_pub_ = create_publisher<std_msgs::msg::Empty>("ping", 1);
    auto ping = [this]() {ping_pub_->publish(std_msgs::msg::Empty());};
    ping_timer_ = std::make_shared<rclcpp::WallTimer<decltype(ping)>>(
      250ms, std::move(ping), get_node_base_interface()->get_context());
    get_node_timers_interface()->add_timer(ping_timer_, nullptr);
  }

private:
  void onTimer()
  {
    if (!enabled_) {
      publishStatus("disabled");
      return;
    }
    sensor_msgs::msg::Range range;
    range.range = 1.0f;
    range_pub_->publish(range);
    publishStatus("ok");
  }

  bool enabled_ = true;
  const std::string range_topic_ = "range";
  rclcpp::Publisher<sensor_msgs::msg::Range>::SharedPtr range_pub_;
  rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr enable_sub_;
  rclcpp::TimerBase::SharedPtr timer_;
  rclcpp::Publisher<std_msgs::msg::Empty>::SharedPtr ping_pub_;
  rclcpp::TimerBase::SharedPtr ping_timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<SonarNode>("front_sonar"));
  rclcpp::shutdown();
  return 0;
}
