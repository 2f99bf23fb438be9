// a component (no executable of its own): a camera at a fixed 20 Hz timer,
// no subscriptions, so its publisher is independent by pattern 1
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace rsia_demo
{

class CameraComponent : public rclcpp::Node
{
public:
  explicit CameraComponent(const rclcpp::NodeOptions & options)
  : Node("camera", options)
  {
    pub_ = create_publisher<sensor_msgs::msg::Image>("image", 5);
    timer_ = create_wall_timer(
      std::chrono::milliseconds(50), [this]() {publishFrame();});
  }

private:
  void publishFrame()
  {
    pub_->publish(sensor_msgs::msg::Image());
  }

  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

}  // namespace rsia_demo

RCLCPP_COMPONENTS_REGISTER_NODE(rsia_demo::CameraComponent)
