// Loops paced by the rclcpp rate objects, in threads of a node that
// subscribes, and one paced by std::this_thread::sleep_for:
// - battery (rclcpp::Rate rate(10)): rate_loop 10 Hz
// - imu (rclcpp::Rate from std::chrono::milliseconds(50)): rate_loop 20 Hz
// - temperature (rclcpp::GenericRate<std::chrono::steady_clock>, Humble and
//   Jazzy; gone in Rolling): rate_loop 5 Hz
// - summary, from main's loop paced by rclcpp::WallRate loop_rate(2.0):
//   rate_loop 2 Hz
// - heartbeat, from a loop paced by sleep_for: no adaptive rate, and the node
//   subscribes, so dependent
// - status, from a loop sleeping on the node's clock until a deadline it
//   advances by rclcpp::Duration::from_seconds(0.25) every pass: rate_loop
//   4 Hz
#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/battery_state.hpp"
#include "sensor_msgs/msg/imu.hpp"
#include "sensor_msgs/msg/temperature.hpp"
#include "std_msgs/msg/empty.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

class RateLoops : public rclcpp::Node
{
public:
  RateLoops()
  : Node("rate_loops")
  {
    battery_pub_ = create_publisher<sensor_msgs::msg::BatteryState>("battery", 10);
    imu_pub_ = create_publisher<sensor_msgs::msg::Imu>("imu", rclcpp::SensorDataQoS());
    temperature_pub_ = create_publisher<sensor_msgs::msg::Temperature>("temperature", 10);
    summary_pub_ = create_publisher<std_msgs::msg::String>("summary", 10);
    heartbeat_pub_ = create_publisher<std_msgs::msg::Empty>("heartbeat", 1);
    status_pub_ = create_publisher<std_msgs::msg::String>("status", 1);
    mode_sub_ = create_subscription<std_msgs::msg::String>(
      "mode", 10,
      [this](std_msgs::msg::String::ConstSharedPtr msg) {fast_ = msg->data == "fast";});

    battery_thread_ = std::thread(&RateLoops::batteryLoop, this);
    imu_thread_ = std::thread([this]() {imuLoop();});
    temperature_thread_ = std::thread(&RateLoops::temperatureLoop, this);
    heartbeat_thread_ = std::thread(&RateLoops::heartbeatLoop, this);
    status_thread_ = std::thread(&RateLoops::statusLoop, this);
  }

  ~RateLoops() override
  {
    battery_thread_.join();
    imu_thread_.join();
    temperature_thread_.join();
    heartbeat_thread_.join();
    status_thread_.join();
  }

  void publishSummary()
  {
    std_msgs::msg::String summary;
    summary.data = fast_ ? "fast" : "slow";
    summary_pub_->publish(summary);
  }

private:
  void batteryLoop()
  {
    rclcpp::Rate rate(10);
    while (rclcpp::ok()) {
      sensor_msgs::msg::BatteryState state;
      state.percentage = 0.5;
      battery_pub_->publish(state);
      rate.sleep();
    }
  }

  void imuLoop()
  {
    rclcpp::Rate rate(std::chrono::milliseconds(50));
    while (rclcpp::ok()) {
      imu_pub_->publish(sensor_msgs::msg::Imu());
      rate.sleep();
    }
  }

  void temperatureLoop()
  {
    rclcpp::GenericRate<std::chrono::steady_clock> rate(5.0);
    while (rclcpp::ok()) {
      sensor_msgs::msg::Temperature temperature;
      temperature.temperature = 21.5;
      temperature_pub_->publish(temperature);
      rate.sleep();
    }
  }

  void heartbeatLoop()
  {
    while (rclcpp::ok()) {
      heartbeat_pub_->publish(std_msgs::msg::Empty());
      std::this_thread::sleep_for(fast_ ? 100ms : 500ms);
    }
  }

  void statusLoop()
  {
    auto next = get_clock()->now();
    while (rclcpp::ok()) {
      next = next + rclcpp::Duration::from_seconds(0.25);
      status_pub_->publish(std_msgs::msg::String());
      get_clock()->sleep_until(next);
    }
  }

  std::atomic<bool> fast_{false};
  rclcpp::Publisher<sensor_msgs::msg::BatteryState>::SharedPtr battery_pub_;
  rclcpp::Publisher<sensor_msgs::msg::Imu>::SharedPtr imu_pub_;
  rclcpp::Publisher<sensor_msgs::msg::Temperature>::SharedPtr temperature_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr summary_pub_;
  rclcpp::Publisher<std_msgs::msg::Empty>::SharedPtr heartbeat_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr mode_sub_;
  std::thread battery_thread_;
  std::thread imu_thread_;
  std::thread temperature_thread_;
  std::thread heartbeat_thread_;
  std::thread status_thread_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<RateLoops>();
  rclcpp::WallRate loop_rate(2.0);
  while (rclcpp::ok()) {
    node->publishSummary();
    rclcpp::spin_some(node);
    loop_rate.sleep();
  }
  rclcpp::shutdown();
  return 0;
}
