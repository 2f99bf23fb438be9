// camera_driver: simulated camera publishing raw + mono images through image_transport.
//
// RSIA patterns covered here:
// - The node offers a service (advertiseService, free-function callback). A service server
//   counts as a subscriber, so pattern 1 (no_subscribers) does NOT apply.
// - The publishing loop in main is paced by a ros::WallRate, whose sleep() is the condition
//   of an `if` at the top level of the loop body (runs on every iteration) -> rate_loop.
// - The frame rate is NOT a compile-time constant (read from the ~fps parameter), so the
//   rate_hz of every publisher is null.
#include <algorithm>
#include <cstdint>
#include <string>

#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <roscpp/Empty.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>

namespace
{

double g_exposure = 0.01;  // seconds, changed by the service and the auto-exposure

void fillRgbFrame(sensor_msgs::Image& image, int width, int height, uint32_t seq)
{
  image.width = width;
  image.height = height;
  image.encoding = sensor_msgs::image_encodings::RGB8;
  image.step = width * 3;
  image.data.resize(image.step * height);
  const uint8_t level = static_cast<uint8_t>(std::min(255.0, 25500.0 * g_exposure));
  for (size_t i = 0; i < image.data.size(); ++i)
  {
    image.data[i] = static_cast<uint8_t>((i + seq) % 64 + level / 2);
  }
}

void toMono(const sensor_msgs::Image& rgb, sensor_msgs::Image& mono)
{
  mono.header = rgb.header;
  mono.width = rgb.width;
  mono.height = rgb.height;
  mono.encoding = sensor_msgs::image_encodings::MONO8;
  mono.step = rgb.width;
  mono.data.resize(rgb.width * rgb.height);
  for (size_t p = 0; p < mono.data.size(); ++p)
  {
    const unsigned sum = rgb.data[3 * p] + rgb.data[3 * p + 1] + rgb.data[3 * p + 2];
    mono.data[p] = static_cast<uint8_t>(sum / 3);
  }
}

}  // namespace

// Service callback (free function): restores the default exposure. Publishes nothing.
bool resetExposure(roscpp::Empty::Request& /*req*/, roscpp::Empty::Response& /*res*/)
{
  g_exposure = 0.01;
  ROS_INFO("camera_driver: exposure reset to %.3f s", g_exposure);
  return true;
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "camera_driver");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");

  // The rate is a run-time parameter, not a constant: rate_hz stays null.
  double fps = 30.0;
  pnh.param("fps", fps, 30.0);
  int width = 160;
  int height = 120;
  pnh.param("width", width, 160);
  pnh.param("height", height, 120);

  image_transport::ImageTransport it(nh);
  // API: image_transport::ImageTransport::advertiseCamera -> two publishers:
  // camera/image_raw (sensor_msgs::Image) and camera/camera_info (sensor_msgs::CameraInfo).
  image_transport::CameraPublisher camera_pub = it.advertiseCamera("camera/image_raw", 1);
  // API: image_transport::ImageTransport::advertise.
  image_transport::Publisher mono_pub = it.advertise("camera/image_mono", 1);

  // API: ros::NodeHandle::advertiseService, free-function form.
  ros::ServiceServer reset_srv = nh.advertiseService("reset_exposure", resetExposure);

  sensor_msgs::CameraInfo info;
  info.width = width;
  info.height = height;
  info.distortion_model = "plumb_bob";
  info.D.assign(5, 0.0);
  info.K = {200.0, 0.0, width / 2.0, 0.0, 200.0, height / 2.0, 0.0, 0.0, 1.0};

  sensor_msgs::Image rgb;
  sensor_msgs::Image mono;
  rgb.header.frame_id = "camera_optical";
  info.header.frame_id = rgb.header.frame_id;
  uint32_t seq = 0;

  // API: ros::WallRate loop; the rate comes from a parameter.
  ros::WallRate loop_rate(fps);
  while (ros::ok())
  {
    fillRgbFrame(rgb, width, height, seq++);
    rgb.header.stamp = ros::Time::now();
    info.header.stamp = rgb.header.stamp;

    // EXPECT camera/image_raw + camera/camera_info: independent, rate_loop (WallRate
    // loop_rate paces this loop), rate_hz null (fps is a parameter).
    camera_pub.publish(rgb, info);

    toMono(rgb, mono);
    // EXPECT camera/image_mono: independent, rate_loop, rate_hz null (same loop).
    mono_pub.publish(mono);

    // Simple auto-exposure towards a mid-grey mono image.
    g_exposure = std::max(0.001, std::min(0.02, g_exposure * (mono.data[0] < 100 ? 1.05 : 0.95)));

    ros::spinOnce();
    // The sleep is the condition of an `if` at the top level of the body: it runs on every
    // iteration, so the loop is paced by loop_rate.
    if (!loop_rate.sleep())
    {
      ROS_WARN_THROTTLE(5.0, "camera_driver: frame took longer than 1/%.1f s", fps);
    }
  }
  return 0;
}
