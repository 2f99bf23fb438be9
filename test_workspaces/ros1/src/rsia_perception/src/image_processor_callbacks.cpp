// image_processor, part 2 of 2: the callbacks. Publishers were created in the constructor
// (image_processor.cpp); the analysis must join both files into one node.
#include <cstdlib>
#include <sstream>

#include <sensor_msgs/image_encodings.h>
#include <std_msgs/String.h>

#include "rsia_perception/image_processor.h"

void ImageProcessor::onImage(const sensor_msgs::ImageConstPtr& image)
{
  ++mono_frames_;
  if (image->encoding != sensor_msgs::image_encodings::MONO8 || image->width < 2)
  {
    publishStatus("unexpected encoding " + image->encoding);
    return;
  }

  // Horizontal gradient magnitude, thresholded.
  sensor_msgs::Image edges;
  edges.header = image->header;
  edges.width = image->width;
  edges.height = image->height;
  edges.encoding = sensor_msgs::image_encodings::MONO8;
  edges.step = image->width;
  edges.data.assign(image->data.size(), 0);
  for (uint32_t row = 0; row < image->height; ++row)
  {
    for (uint32_t col = 1; col < image->width; ++col)
    {
      const size_t i = row * image->step + col;
      const int gradient = std::abs(int(image->data[i]) - int(image->data[i - 1]));
      edges.data[row * edges.step + col] = gradient > edge_threshold_ ? 255 : 0;
    }
  }
  // EXPECT edges: dependent, none (image_transport subscriber callback).
  edges_pub_.publish(edges);
}

void ImageProcessor::onCameraImage(const sensor_msgs::ImageConstPtr& image,
                                   const sensor_msgs::CameraInfoConstPtr& info)
{
  ++raw_frames_;
  if (info->width != image->width || info->height != image->height)
  {
    // Reaches publishStatus() from a subscriber callback too.
    publishStatus("camera_info does not match the image size");
  }
}

void ImageProcessor::onStatsTimer(const ros::TimerEvent& /*event*/)
{
  std_msgs::String stats;
  std::ostringstream text;
  text << "mono=" << mono_frames_ << " raw=" << raw_frames_;
  stats.data = text.str();
  // EXPECT processor_stats: independent, timer (only reached from the 1 Hz timer callback),
  // rate_hz 1.0.
  stats_pub_.publish(stats);

  if (mono_frames_ == 0)
  {
    publishStatus("no images received yet");
  }
}

void ImageProcessor::publishStatus(const std::string& text)
{
  std_msgs::String status;
  status.data = text;
  // EXPECT processor_status: dependent, none. This helper is called from the timer callback
  // (independent path) AND from the subscriber callbacks onImage/onCameraImage (dependent
  // paths); one dependent path makes the publisher dependent.
  status_pub_.publish(status);
}
