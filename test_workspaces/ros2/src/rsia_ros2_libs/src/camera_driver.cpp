// A camera driver: grabs a frame from a 50 ms wall timer and publishes image
// + camera_info through image_transport::create_camera_publisher. The only
// input is a service that changes the exposure (it publishes nothing).
#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "image_transport/image_transport.hpp"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/camera_info.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "std_srvs/srv/set_bool.hpp"

using namespace std::chrono_literals;

class CameraDriver : public rclcpp::Node
{
public:
  CameraDriver()
  : Node("camera_driver")
  {
    frame_id_ = declare_parameter<std::string>("frame_id", "camera_optical");
    camera_pub_ = image_transport::create_camera_publisher(
      this, "camera/image_raw", rmw_qos_profile_sensor_data);
    exposure_srv_ = create_service<std_srvs::srv::SetBool>(
      "set_auto_exposure",
      std::bind(
        &CameraDriver::onSetAutoExposure, this, std::placeholders::_1,
        std::placeholders::_2));
    timer_ = create_wall_timer(50ms, std::bind(&CameraDriver::grab, this));
  }

private:
  void grab()
  {
    auto image = std::make_unique<sensor_msgs::msg::Image>();
    auto info = std::make_unique<sensor_msgs::msg::CameraInfo>();
    image->header.stamp = now();
    image->header.frame_id = frame_id_;
    image->encoding = "bgr8";
    info->header = image->header;
    if (auto_exposure_) {
      image->step = 3 * image->width;
    }
    camera_pub_.publish(std::move(image), std::move(info));
  }

  void onSetAutoExposure(
    const std::shared_ptr<std_srvs::srv::SetBool::Request> request,
    std::shared_ptr<std_srvs::srv::SetBool::Response> response)
  {
    auto_exposure_ = request->data;
    response->success = true;
  }

  std::string frame_id_;
  bool auto_exposure_{true};
  image_transport::CameraPublisher camera_pub_;
  rclcpp::Service<std_srvs::srv::SetBool>::SharedPtr exposure_srv_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<CameraDriver>());
  rclcpp::shutdown();
  return 0;
}
