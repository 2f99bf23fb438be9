// An image relay: subscribes with image_transport::create_subscription and
// republishes every frame (create_publisher) and a half-size thumbnail
// (ImageTransport::advertise, set up after construction because it needs
// shared_from_this()). Every publish happens in the image callback.
#include <functional>
#include <memory>

#include "image_transport/image_transport.hpp"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/image.hpp"

class ImageRelay : public rclcpp::Node
{
public:
  ImageRelay()
  : Node("image_relay")
  {
    relay_pub_ = image_transport::create_publisher(this, "image_out");
    image_sub_ = image_transport::create_subscription(
      this, "image_in",
      std::bind(&ImageRelay::onImage, this, std::placeholders::_1),
      "raw", rmw_qos_profile_sensor_data);
  }

  void init()
  {
    it_ = std::make_shared<image_transport::ImageTransport>(shared_from_this());
    thumb_pub_ = it_->advertise("image_thumb", 1);
  }

private:
  void onImage(const sensor_msgs::msg::Image::ConstSharedPtr & msg)
  {
    relay_pub_.publish(msg);
    if (thumb_pub_.getNumSubscribers() > 0) {
      sensor_msgs::msg::Image thumb;
      thumb.header = msg->header;
      thumb.width = msg->width / 2;
      thumb.height = msg->height / 2;
      thumb_pub_.publish(thumb);
    }
  }

  std::shared_ptr<image_transport::ImageTransport> it_;
  image_transport::Publisher relay_pub_;
  image_transport::Publisher thumb_pub_;
  image_transport::Subscriber image_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<ImageRelay>();
  node->init();
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
