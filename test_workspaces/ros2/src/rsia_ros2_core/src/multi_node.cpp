// Two node classes in one executable, spun in one multi-threaded executor:
// each is its own node (rsia_ros2_core/multi_node/camera and .../detector).
// - camera subscribes to nothing: image is independent by pattern 1
// - detector publishes detections from its image callback: dependent; its
//   ~/rate comes from a 2 Hz timer: independent
#include <chrono>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "std_msgs/msg/float64.hpp"
#include "std_msgs/msg/string.hpp"

using namespace std::chrono_literals;

class Camera : public rclcpp::Node
{
public:
  explicit Camera(const rclcpp::NodeOptions & options)
  : Node("camera", options)
  {
    image_pub_ = create_publisher<sensor_msgs::msg::Image>("image", rclcpp::SensorDataQoS());
    timer_ = create_wall_timer(40ms, std::bind(&Camera::capture, this));
  }

private:
  void capture()
  {
    auto image = std::make_unique<sensor_msgs::msg::Image>();
    image->header.stamp = now();
    image_pub_->publish(std::move(image));
  }

  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr image_pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

class Detector : public rclcpp::Node
{
public:
  Detector()
  : Node("detector")
  {
    detections_pub_ = create_publisher<std_msgs::msg::String>("detections", 10);
    rate_pub_ = create_publisher<std_msgs::msg::Float64>("~/rate", 1);
    image_sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image", rclcpp::SensorDataQoS(),
      [this](sensor_msgs::msg::Image::UniquePtr image) {detect(*image);});
    rate_timer_ = create_wall_timer(500ms, [this]() {publishRate();});
  }

private:
  void detect(const sensor_msgs::msg::Image & image)
  {
    ++frames_;
    std_msgs::msg::String detections;
    detections.data = image.encoding;
    detections_pub_->publish(detections);
  }

  void publishRate()
  {
    std_msgs::msg::Float64 rate;
    rate.data = frames_ * 2.0;
    frames_ = 0;
    rate_pub_->publish(rate);
  }

  int frames_ = 0;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr detections_pub_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr rate_pub_;
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr image_sub_;
  rclcpp::TimerBase::SharedPtr rate_timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::NodeOptions options;
  options.use_intra_process_comms(true);
  auto camera = std::make_shared<Camera>(options);
  auto detector = std::make_shared<Detector>();
  rclcpp::executors::MultiThreadedExecutor executor;
  executor.add_node(camera);
  executor.add_node(detector);
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
