// Callback forms: std::function members handed to create_subscription,
// create_wall_timer and create_service; a timer made after construction
// from shared_from_this(); subscription callbacks taking
// std::shared_ptr<const M>, M::ConstSharedPtr and M::SharedPtr.
// - alive comes from the 1 s timer whose callback is the lambda stored in
//   the std::function member tick_: independent (timer)
// - report comes from the 10 Hz timer created in init(): independent (timer)
// - warnings are published from the battery callback (a std::function
//   member bound to Monitor::onBattery) and from the temperature lambda:
//   dependent
#include <chrono>
#include <functional>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/battery_state.hpp"
#include "sensor_msgs/msg/imu.hpp"
#include "sensor_msgs/msg/temperature.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/float32.hpp"
#include "std_msgs/msg/string.hpp"
#include "std_srvs/srv/empty.hpp"

using namespace std::chrono_literals;
using std::placeholders::_1;
using std::placeholders::_2;

class Monitor : public rclcpp::Node
{
public:
  Monitor()
  : Node("monitor")
  {
    alive_pub_ = create_publisher<std_msgs::msg::Bool>("alive", 1);
    report_pub_ = create_publisher<std_msgs::msg::Float32>("report", 10);
    warn_pub_ = create_publisher<std_msgs::msg::String>("warnings", 10);

    on_battery_ = std::bind(&Monitor::onBattery, this, _1);
    battery_sub_ = create_subscription<sensor_msgs::msg::BatteryState>(
      "battery", 10, on_battery_);
    temperature_sub_ = create_subscription<sensor_msgs::msg::Temperature>(
      "temperature", 10,
      [this](std::shared_ptr<const sensor_msgs::msg::Temperature> msg) {
        if (msg->temperature > 60.0) {
          std_msgs::msg::String warning;
          warning.data = "hot";
          warn_pub_->publish(warning);
        }
      });
    imu_sub_ = create_subscription<sensor_msgs::msg::Imu>(
      "imu", rclcpp::SensorDataQoS(), std::bind(&Monitor::onImu, this, _1));

    tick_ = [this]() {
        std_msgs::msg::Bool alive;
        alive.data = true;
        alive_pub_->publish(alive);
      };
    alive_timer_ = create_wall_timer(1s, tick_);

    on_reset_ = std::bind(&Monitor::onReset, this, _1, _2);
    reset_srv_ = create_service<std_srvs::srv::Empty>("reset", on_reset_);
  }

  // shared_from_this() is not usable in the constructor
  void init()
  {
    auto self = std::static_pointer_cast<Monitor>(shared_from_this());
    report_timer_ = create_wall_timer(100ms, [self]() {self->step();});
  }

private:
  void step()
  {
    std_msgs::msg::Float32 report;
    report.data = charge_;
    report_pub_->publish(report);
  }

  void onBattery(sensor_msgs::msg::BatteryState::ConstSharedPtr msg)
  {
    charge_ = msg->percentage;
    if (charge_ < 0.2f) {
      std_msgs::msg::String warning;
      warning.data = "battery low";
      warn_pub_->publish(warning);
    }
  }

  void onImu(const sensor_msgs::msg::Imu::SharedPtr msg)
  {
    last_imu_ = *msg;
  }

  void onReset(
    const std::shared_ptr<std_srvs::srv::Empty::Request> request,
    std::shared_ptr<std_srvs::srv::Empty::Response> response)
  {
    (void)request;
    (void)response;
    charge_ = 1.0f;
  }

  float charge_ = 1.0f;
  sensor_msgs::msg::Imu last_imu_;
  std::function<void(sensor_msgs::msg::BatteryState::ConstSharedPtr)> on_battery_;
  std::function<void()> tick_;
  std::function<void(
      const std::shared_ptr<std_srvs::srv::Empty::Request>,
      std::shared_ptr<std_srvs::srv::Empty::Response>)> on_reset_;
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr alive_pub_;
  rclcpp::Publisher<std_msgs::msg::Float32>::SharedPtr report_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr warn_pub_;
  rclcpp::Subscription<sensor_msgs::msg::BatteryState>::SharedPtr battery_sub_;
  rclcpp::Subscription<sensor_msgs::msg::Temperature>::SharedPtr temperature_sub_;
  rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr imu_sub_;
  rclcpp::TimerBase::SharedPtr alive_timer_;
  rclcpp::TimerBase::SharedPtr report_timer_;
  rclcpp::Service<std_srvs::srv::Empty>::SharedPtr reset_srv_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Monitor>();
  node->init();
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
