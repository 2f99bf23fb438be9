// image_processor, part 1 of 2: the constructor (every handle is created here) and main.
// The callbacks that publish live in image_processor_callbacks.cpp.
#include "rsia_perception/image_processor.h"

#include <std_msgs/String.h>

ImageProcessor::ImageProcessor(ros::NodeHandle& nh) : it_(nh)
{
  ros::NodeHandle pnh("~");
  pnh.param("edge_threshold", edge_threshold_, 40);

  // API: image_transport::ImageTransport::subscribe, member function + this.
  image_sub_ = it_.subscribe("camera/image_mono", 1, &ImageProcessor::onImage, this);
  // API: image_transport::ImageTransport::subscribeCamera, member function + this
  // (two subscribers: camera/image_raw and camera/camera_info).
  camera_sub_ = it_.subscribeCamera("camera/image_raw", 1, &ImageProcessor::onCameraImage, this);

  // API: image_transport::ImageTransport::advertise.
  edges_pub_ = it_.advertise("edges", 1);
  stats_pub_ = nh.advertise<std_msgs::String>("processor_stats", 1);
  status_pub_ = nh.advertise<std_msgs::String>("processor_status", 5);

  // API: ros::NodeHandle::createTimer, Duration form with a member callback (1.0 s -> 1 Hz).
  stats_timer_ = nh.createTimer(ros::Duration(1.0), &ImageProcessor::onStatsTimer, this);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "image_processor");
  ros::NodeHandle nh;
  ImageProcessor processor(nh);
  ros::spin();
  return 0;
}
