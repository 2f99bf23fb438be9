// Every publish overload of rclcpp::Publisher from one 20 Hz wall timer:
// by const reference through a local copy of the publisher's shared_ptr,
// by std::unique_ptr through the lock() of a weak_ptr to `this->twist_pub_`,
// and a loaned message
// (borrow_loaned_message + publish(LoanedMessage&&)). All three are
// independent (timer) although the node subscribes; the stamp echo is
// published from the subscription callback: dependent.
#include <chrono>
#include <memory>
#include <utility>

#include "rclcpp/rclcpp.hpp"
#include "geometry_msgs/msg/pose_stamped.hpp"
#include "geometry_msgs/msg/twist.hpp"
#include "std_msgs/msg/float64.hpp"
#include "std_msgs/msg/header.hpp"

using namespace std::chrono_literals;

class PublishForms : public rclcpp::Node
{
public:
  PublishForms()
  : Node("publish_forms", rclcpp::NodeOptions().use_intra_process_comms(true))
  {
    pose_pub_ = create_publisher<geometry_msgs::msg::PoseStamped>("pose", 10);
    twist_pub_ = this->create_publisher<geometry_msgs::msg::Twist>("twist", 10);
    level_pub_ = create_publisher<std_msgs::msg::Float64>("level", 10);
    echo_pub_ = create_publisher<std_msgs::msg::Header>("stamp_echo", 10);
    stamp_sub_ = create_subscription<std_msgs::msg::Header>(
      "stamp", 10,
      [this](const std_msgs::msg::Header & header) {onStamp(header);});
    timer_ = create_wall_timer(50ms, [this]() {tick();});
  }

private:
  void tick()
  {
    geometry_msgs::msg::PoseStamped pose;
    pose.header.stamp = now();
    auto publisher = pose_pub_;
    publisher->publish(pose);

    auto twist = std::make_unique<geometry_msgs::msg::Twist>();
    twist->linear.x = 0.1;
    std::weak_ptr<rclcpp::Publisher<geometry_msgs::msg::Twist>> weak_twist =
      this->twist_pub_;
    if (auto locked = weak_twist.lock()) {
      locked->publish(std::move(twist));
    }

    if (level_pub_->can_loan_messages()) {
      auto loaned = level_pub_->borrow_loaned_message();
      loaned.get().data = level_;
      level_pub_->publish(std::move(loaned));
    } else {
      std_msgs::msg::Float64 level;
      level.data = level_;
      level_pub_->publish(level);
    }
  }

  void onStamp(const std_msgs::msg::Header & header)
  {
    level_ += 1.0;
    this->echo_pub_->publish(header);
  }

  double level_ = 0.0;
  rclcpp::Publisher<geometry_msgs::msg::PoseStamped>::SharedPtr pose_pub_;
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr twist_pub_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr level_pub_;
  rclcpp::Publisher<std_msgs::msg::Header>::SharedPtr echo_pub_;
  rclcpp::Subscription<std_msgs::msg::Header>::SharedPtr stamp_sub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<PublishForms>();
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
