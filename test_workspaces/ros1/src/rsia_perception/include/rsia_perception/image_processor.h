// ImageProcessor: one class split over two translation units.
//   src/image_processor.cpp            constructor (creates every publisher, subscriber, timer) + main
//   src/image_processor_callbacks.cpp  the callbacks and the shared publishStatus() helper
#ifndef RSIA_PERCEPTION__IMAGE_PROCESSOR_H_
#define RSIA_PERCEPTION__IMAGE_PROCESSOR_H_

#include <cstdint>
#include <string>

#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

class ImageProcessor
{
public:
  explicit ImageProcessor(ros::NodeHandle& nh);

  // image_transport subscriber callback (camera/image_mono).
  void onImage(const sensor_msgs::ImageConstPtr& image);
  // image_transport camera subscriber callback (camera/image_raw + camera/camera_info).
  void onCameraImage(const sensor_msgs::ImageConstPtr& image,
                     const sensor_msgs::CameraInfoConstPtr& info);
  // Timer callback (1 Hz).
  void onStatsTimer(const ros::TimerEvent& event);

private:
  // Helper called from BOTH the timer callback and the subscriber callbacks.
  void publishStatus(const std::string& text);

  image_transport::ImageTransport it_;
  image_transport::Subscriber image_sub_;
  image_transport::CameraSubscriber camera_sub_;
  image_transport::Publisher edges_pub_;
  ros::Publisher stats_pub_;
  ros::Publisher status_pub_;
  ros::Timer stats_timer_;

  uint64_t mono_frames_ = 0;
  uint64_t raw_frames_ = 0;
  int edge_threshold_ = 40;
};

#endif  // RSIA_PERCEPTION__IMAGE_PROCESSOR_H_
