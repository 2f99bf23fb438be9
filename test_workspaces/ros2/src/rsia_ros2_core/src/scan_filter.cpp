// Topic names from parameters declared with defaults, a private topic, a
// ROS-time timer of Node::create_timer (Jazzy+) and unique_ptr messages.
// - the filtered scan is published from the scan callback: dependent
// - ~/status is published from the 1 s node-clock timer: independent
// - the parameter callback (add_on_set_parameters_callback) is no
//   subscription and publishes nothing
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "rclcpp/rclcpp.hpp"
#include "rcl_interfaces/msg/set_parameters_result.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

class ScanFilter : public rclcpp::Node
{
public:
  explicit ScanFilter(const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : Node("scan_filter", options)
  {
    declare_parameter("input_topic", "scan");
    auto topic = declare_parameter<std::string>("output_topic", "scan_filtered");
    range_max_ = declare_parameter("range_max", 30.0);

    pub_ = create_publisher<sensor_msgs::msg::LaserScan>(topic, 10);
    status_pub_ = create_publisher<std_msgs::msg::String>("~/status", 1);
    sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
      get_parameter("input_topic").as_string(), rclcpp::SensorDataQoS(),
      std::bind(&ScanFilter::onScan, this, std::placeholders::_1));

    status_timer_ = create_timer(1s, std::bind(&ScanFilter::publishStatus, this));

    param_handle_ = add_on_set_parameters_callback(
      [this](const std::vector<rclcpp::Parameter> & parameters) {
        rcl_interfaces::msg::SetParametersResult result;
        result.successful = true;
        for (const auto & parameter : parameters) {
          if (parameter.get_name() == "range_max") {
            range_max_ = parameter.as_double();
          }
        }
        return result;
      });
  }

private:
  void onScan(sensor_msgs::msg::LaserScan::UniquePtr scan)
  {
    ++received_;
    scan->range_max = range_max_;
    pub_->publish(std::move(scan));
  }

  void publishStatus()
  {
    auto status = std::make_unique<std_msgs::msg::String>();
    status->data = "received " + std::to_string(received_);
    status_pub_->publish(std::move(status));
  }

  double range_max_;
  uint64_t received_ = 0;
  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr sub_;
  rclcpp::TimerBase::SharedPtr status_timer_;
  OnSetParametersCallbackHandle::SharedPtr param_handle_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ScanFilter>());
  rclcpp::shutdown();
  return 0;
}
