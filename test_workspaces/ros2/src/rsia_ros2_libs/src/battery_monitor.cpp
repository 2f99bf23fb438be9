// A battery monitor: a diagnostic_updater::Updater made with a 0.5 s period
// (its own timer publishes /diagnostics twice a second; the node never calls
// update() or force_update()), fed from a battery_state subscription whose
// callback also republishes the charge percentage.
#include <functional>
#include <memory>

#include "diagnostic_updater/diagnostic_updater.hpp"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/battery_state.hpp"
#include "std_msgs/msg/float32.hpp"

class BatteryMonitor : public rclcpp::Node
{
public:
  BatteryMonitor()
  : Node("battery_monitor"),
    updater_(this, 0.5)
  {
    updater_.setHardwareID("bms0");
    updater_.add("Battery voltage", this, &BatteryMonitor::checkVoltage);
    percent_pub_ = create_publisher<std_msgs::msg::Float32>("battery_percent", 10);
    battery_sub_ = create_subscription<sensor_msgs::msg::BatteryState>(
      "battery_state", rclcpp::SensorDataQoS(),
      std::bind(&BatteryMonitor::onBattery, this, std::placeholders::_1));
  }

private:
  void onBattery(const sensor_msgs::msg::BatteryState & msg)
  {
    voltage_ = msg.voltage;
    std_msgs::msg::Float32 percent;
    percent.data = 100.0f * msg.percentage;
    percent_pub_->publish(percent);
  }

  void checkVoltage(diagnostic_updater::DiagnosticStatusWrapper & stat)
  {
    if (voltage_ < 22.0) {
      stat.summary(diagnostic_msgs::msg::DiagnosticStatus::WARN, "low voltage");
    } else {
      stat.summary(diagnostic_msgs::msg::DiagnosticStatus::OK, "ok");
    }
    stat.add("voltage", voltage_);
  }

  double voltage_{0.0};
  diagnostic_updater::Updater updater_;
  rclcpp::Publisher<std_msgs::msg::Float32>::SharedPtr percent_pub_;
  rclcpp::Subscription<sensor_msgs::msg::BatteryState>::SharedPtr battery_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<BatteryMonitor>());
  rclcpp::shutdown();
  return 0;
}
