// colcon-rsia model of <tf2_ros/buffer.h>: tf2_ros::Buffer (the timeout forms
// of lookupTransform/canTransform, and those of tf2::BufferCore by `using`).
#ifndef RSIA_MODEL_TF2_ROS_BUFFER_H
#define RSIA_MODEL_TF2_ROS_BUFFER_H

// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
#ifdef RSIA_MODEL_RCLCPP
#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <string>

#include <geometry_msgs/msg/transform_stamped.hpp>
#include <rclcpp/rclcpp.hpp>
#include <tf2/exceptions.h>
#include <tf2_ros/create_timer_interface.h>

// tf2/time.h (ROS 2), which the real tf2_ros/buffer.h includes
#ifndef RSIA_MODEL_TF2_TIME_H
#define RSIA_MODEL_TF2_TIME_H
namespace tf2
{
using Duration = std::chrono::nanoseconds;
using TimePoint = std::chrono::time_point<std::chrono::system_clock, Duration>;
using IDuration = std::chrono::duration<int, std::nano>;
static const TimePoint TimePointZero = TimePoint(IDuration::zero());
TimePoint get_now();
Duration durationFromSec(double t_sec);
TimePoint timeFromSec(double t_sec);
double durationToSec(const tf2::Duration & input);
double timeToSec(const TimePoint & timepoint);
std::string displayTimePoint(const TimePoint & stamp);
}  // namespace tf2
#endif  // RSIA_MODEL_TF2_TIME_H

namespace tf2
{
static constexpr int BUFFER_CORE_DEFAULT_CACHE_TIME = 10;
}  // namespace tf2

namespace tf2_ros
{

using TransformStampedFuture =
  std::shared_future<geometry_msgs::msg::TransformStamped>;
using TransformReadyCallback = std::function<void (const TransformStampedFuture &)>;

// Humble: (clock, cache_time = 10 s, rclcpp::Node::SharedPtr node = {});
// Jazzy+: the node is a template, and a QoS for the tf2_frames service
class Buffer
{
public:
  template<typename NodeT = rclcpp::Node::SharedPtr>
  explicit Buffer(
    rclcpp::Clock::SharedPtr clock,
    tf2::Duration cache_time = tf2::Duration(
      std::chrono::seconds(tf2::BUFFER_CORE_DEFAULT_CACHE_TIME)),
    NodeT && node = NodeT(),
    const rclcpp::QoS & qos = rclcpp::ServicesQoS());

  // tf2::BufferCore's forms (by `using` in the real class)
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const std::string & source_frame,
    const tf2::TimePoint & time) const;
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const tf2::TimePoint & target_time,
    const std::string & source_frame, const tf2::TimePoint & source_time,
    const std::string & fixed_frame) const;
  // tf2_ros::Buffer's own
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const std::string & source_frame,
    const tf2::TimePoint & time, const tf2::Duration timeout) const;
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const std::string & source_frame,
    const rclcpp::Time & time,
    const rclcpp::Duration timeout = rclcpp::Duration::from_nanoseconds(0)) const;
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const tf2::TimePoint & target_time,
    const std::string & source_frame, const tf2::TimePoint & source_time,
    const std::string & fixed_frame, const tf2::Duration timeout) const;
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const rclcpp::Time & target_time,
    const std::string & source_frame, const rclcpp::Time & source_time,
    const std::string & fixed_frame,
    const rclcpp::Duration timeout = rclcpp::Duration::from_nanoseconds(0)) const;
  // a stamp taken from a message field (a stand-in's catch-all member)
  template<class TimeT>
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const std::string & source_frame,
    const TimeT & time) const;
  template<class TimeT, class DurationT>
  geometry_msgs::msg::TransformStamped lookupTransform(
    const std::string & target_frame, const std::string & source_frame,
    const TimeT & time, const DurationT timeout) const;

  bool canTransform(
    const std::string & target_frame, const std::string & source_frame,
    const tf2::TimePoint & time, std::string * error_msg = nullptr) const;
  bool canTransform(
    const std::string & target_frame, const std::string & source_frame,
    const tf2::TimePoint & target_time, const tf2::Duration timeout,
    std::string * errstr = nullptr) const;
  bool canTransform(
    const std::string & target_frame, const std::string & source_frame,
    const rclcpp::Time & time,
    const rclcpp::Duration timeout = rclcpp::Duration::from_nanoseconds(0),
    std::string * errstr = nullptr) const;
  template<class TimeT>
  bool canTransform(
    const std::string & target_frame, const std::string & source_frame,
    const TimeT & time, std::string * errstr = nullptr) const;

  TransformStampedFuture waitForTransform(
    const std::string & target_frame, const std::string & source_frame,
    const tf2::TimePoint & time, const tf2::Duration & timeout,
    TransformReadyCallback callback);
  TransformStampedFuture waitForTransform(
    const std::string & target_frame, const std::string & source_frame,
    const rclcpp::Time & time, const rclcpp::Duration & timeout,
    TransformReadyCallback callback);

  template<class T>
  T & transform(
    const T & in, T & out, const std::string & target_frame,
    tf2::Duration timeout = tf2::Duration(0)) const;
  template<class T>
  T transform(
    const T & in, const std::string & target_frame,
    tf2::Duration timeout = tf2::Duration(0)) const;
  template<class A, class B>
  B & transform(
    const A & in, B & out, const std::string & target_frame,
    tf2::Duration timeout = tf2::Duration(0)) const;

  void setCreateTimerInterface(CreateTimerInterface::SharedPtr create_timer_interface);
  void setUsingDedicatedThread(bool value);
  bool isUsingDedicatedThread() const;
  std::string allFramesAsString() const;
  std::string allFramesAsYAML() const;
  void clear();
};

}  // namespace tf2_ros
#else  // ROS 1

#include <string>

#include <ros/ros.h>
#include <tf2/buffer_core.h>
#include <tf2_ros/buffer_interface.h>

namespace tf2_ros
{

class Buffer : public BufferInterface, public tf2::BufferCore
{
public:
  using tf2::BufferCore::lookupTransform;
  using tf2::BufferCore::canTransform;

  Buffer(ros::Duration cache_time = ros::Duration(BufferCore::DEFAULT_CACHE_TIME), bool debug = false);

  virtual geometry_msgs::TransformStamped lookupTransform(const std::string& target_frame,
                                                          const std::string& source_frame,
                                                          const ros::Time& time,
                                                          const ros::Duration timeout) const;
  virtual geometry_msgs::TransformStamped lookupTransform(const std::string& target_frame,
                                                          const ros::Time& target_time,
                                                          const std::string& source_frame,
                                                          const ros::Time& source_time,
                                                          const std::string& fixed_frame,
                                                          const ros::Duration timeout) const;
  virtual bool canTransform(const std::string& target_frame, const std::string& source_frame,
                            const ros::Time& target_time, const ros::Duration timeout,
                            std::string* errstr = NULL) const;
  virtual bool canTransform(const std::string& target_frame, const ros::Time& target_time,
                            const std::string& source_frame, const ros::Time& source_time,
                            const std::string& fixed_frame, const ros::Duration timeout,
                            std::string* errstr = NULL) const;
};

static const std::string threading_error = "Do not call canTransform or lookupTransform with a timeout "
                                           "unless another thread populates the buffer.";

}  // namespace tf2_ros

#endif  // RSIA_MODEL_RCLCPP

#endif  // RSIA_MODEL_TF2_ROS_BUFFER_H
