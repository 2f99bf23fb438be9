// a relay: echo is published from the subscription (dependent), status from
// a 2 Hz timer created with std::chrono::milliseconds (independent)
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
#include "std_msgs/msg/int32.hpp"

constexpr auto kStatusPeriod = std::chrono::milliseconds(500);

class Relay : public rclcpp::Node
{
public:
  Relay()
  : Node("relay")
  {
    echo_pub_ = this->create_publisher<std_msgs::msg::String>("echo", 10);
    status_pub_ = this->create_publisher<std_msgs::msg::Int32>(
      "status", rclcpp::QoS(1).transient_local());
    sub_ = this->create_subscription<std_msgs::msg::String>(
      "chatter", 10,
      std::bind(&Relay::onChatter, this, std::placeholders::_1));
    timer_ = this->create_wall_timer(
      kStatusPeriod, [this]() {publishStatus();});
  }

private:
  void onChatter(const std_msgs::msg::String::SharedPtr msg)
  {
    auto out = std::make_unique<std_msgs::msg::String>();
    out->data = msg->data;
    echo_pub_->publish(std::move(out));
    ++count_;
  }

  void publishStatus()
  {
    std_msgs::msg::Int32 status;
    status.data = count_;
    status_pub_->publish(status);
  }

  int count_ = 0;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr echo_pub_;
  rclcpp::Publisher<std_msgs::msg::Int32>::SharedPtr status_pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Relay>());
  rclcpp::shutdown();
  return 0;
}
