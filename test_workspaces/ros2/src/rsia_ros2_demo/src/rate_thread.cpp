// a Rate-paced loop in a thread (independent, rate_loop 10 Hz) in a node that
// subscribes (lambda callback, const reference); a tf broadcaster sending from
// the subscription callback (dependent)
#include <memory>
#include <thread>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/float64.hpp"
#include "geometry_msgs/msg/transform_stamped.hpp"
#include "tf2_ros/transform_broadcaster.h"

class RateThread : public rclcpp::Node
{
public:
  RateThread()
  : Node("rate_thread")
  {
    pub_ = create_publisher<std_msgs::msg::Float64>("level", 10);
    broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>(*this);
    sub_ = create_subscription<std_msgs::msg::Float64>(
      "setpoint", 10,
      [this](const std_msgs::msg::Float64 & msg) {
        setpoint_ = msg.data;
        geometry_msgs::msg::TransformStamped t;
        broadcaster_->sendTransform(t);
      });
    worker_ = std::thread([this] {
        rclcpp::Rate rate(10);
        while (rclcpp::ok()) {
          std_msgs::msg::Float64 out;
          out.data = setpoint_;
          pub_->publish(out);
          rate.sleep();
        }
      });
  }

private:
  double setpoint_ = 0.0;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::Float64>::SharedPtr sub_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> broadcaster_;
  std::thread worker_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<RateThread>());
  rclcpp::shutdown();
  return 0;
}
