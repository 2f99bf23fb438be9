// A stereo matcher: two message_filters::Subscriber inputs joined by an
// ApproximateTime Synchronizer (made with std::make_shared of a type alias);
// the synchronized callback publishes the disparity. A 1 s timer lambda
// reports how many pairs were matched. The includes are sorted the way
// ament_cpplint wants them: message_filters comes before rclcpp.
#include <chrono>
#include <functional>
#include <memory>

#include "message_filters/subscriber.h"
#include "message_filters/sync_policies/approximate_time.h"
#include "message_filters/synchronizer.h"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "std_msgs/msg/u_int32.hpp"
#include "stereo_msgs/msg/disparity_image.hpp"

using namespace std::chrono_literals;

class StereoSync : public rclcpp::Node
{
public:
  using Image = sensor_msgs::msg::Image;
  using SyncPolicy = message_filters::sync_policies::ApproximateTime<Image, Image>;
  using Sync = message_filters::Synchronizer<SyncPolicy>;

  StereoSync()
  : Node("stereo_sync")
  {
    disparity_pub_ = create_publisher<stereo_msgs::msg::DisparityImage>("disparity", 1);
    status_pub_ = create_publisher<std_msgs::msg::UInt32>("stereo/pairs", 10);
    left_sub_.subscribe(this, "left/image_rect", rmw_qos_profile_sensor_data);
    right_sub_.subscribe(this, "right/image_rect", rmw_qos_profile_sensor_data);
    sync_ = std::make_shared<Sync>(SyncPolicy(10), left_sub_, right_sub_);
    sync_->registerCallback(
      std::bind(
        &StereoSync::onPair, this, std::placeholders::_1,
        std::placeholders::_2));
    status_timer_ = create_wall_timer(
      1s, [this]() {
        std_msgs::msg::UInt32 count;
        count.data = pairs_;
        status_pub_->publish(count);
      });
  }

private:
  void onPair(const Image::ConstSharedPtr & left, const Image::ConstSharedPtr & right)
  {
    ++pairs_;
    auto disparity = std::make_unique<stereo_msgs::msg::DisparityImage>();
    disparity->header = left->header;
    disparity->image.width = right->width;
    disparity_pub_->publish(std::move(disparity));
  }

  uint32_t pairs_{0};
  message_filters::Subscriber<Image> left_sub_;
  message_filters::Subscriber<Image> right_sub_;
  std::shared_ptr<Sync> sync_;
  rclcpp::Publisher<stereo_msgs::msg::DisparityImage>::SharedPtr disparity_pub_;
  rclcpp::Publisher<std_msgs::msg::UInt32>::SharedPtr status_pub_;
  rclcpp::TimerBase::SharedPtr status_timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<StereoSync>());
  rclcpp::shutdown();
  return 0;
}
