// A robot node that publishes its sensors from one timer, through a base
// class: the timer calls Sensor::publish, a pure virtual method, and the
// override Imu::publish is what publishes.
#include <chrono>
#include <memory>
#include <vector>

#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/imu.hpp>

using namespace std::chrono_literals;

namespace sensors
{
class Sensor
{
public:
  virtual ~Sensor() = default;
  virtual void publish(const rclcpp::Time & now) = 0;
};

class Imu : public Sensor
{
public:
  explicit Imu(rclcpp::Node * node)
  {
    pub_ = node->create_publisher<sensor_msgs::msg::Imu>("imu", 10);
  }

  void publish(const rclcpp::Time & now) override
  {
    sensor_msgs::msg::Imu msg;
    msg.header.stamp = now;
    pub_->publish(msg);
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::Imu>::SharedPtr pub_;
};
}  // namespace sensors

class SensorSuite : public rclcpp::Node
{
public:
  SensorSuite()
  : Node("sensor_suite")
  {
    sensors_.push_back(std::make_shared<sensors::Imu>(this));
    calibration_ = create_subscription<sensor_msgs::msg::Imu>(
      "imu_calibration", 1, [](sensor_msgs::msg::Imu::SharedPtr) {});
    timer_ = create_wall_timer(20ms, [this]() {
        for (auto & sensor : sensors_) {
          sensor->publish(now());
        }
      });
  }

private:
  std::vector<std::shared_ptr<sensors::Sensor>> sensors_;
  rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr calibration_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<SensorSuite>());
  rclcpp::shutdown();
  return 0;
}
