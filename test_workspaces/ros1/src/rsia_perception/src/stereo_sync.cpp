// stereo_sync: time-synchronised processing with message_filters.
//
// API covered: message_filters::Subscriber (topic = 2nd constructor argument), fed into
//   - a message_filters::TimeSynchronizer (exact stamps), callback registered with boost::bind;
//   - a message_filters::Synchronizer with an ApproximateTime policy, callback registered as
//     member function pointer + this.
// Both publishers publish from the synchronizer callbacks -> dependent.
#include <cmath>

#include <boost/bind/bind.hpp>
#include <message_filters/subscriber.h>
#include <message_filters/sync_policies/approximate_time.h>
#include <message_filters/synchronizer.h>
#include <message_filters/time_synchronizer.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/LaserScan.h>

using namespace boost::placeholders;

class StereoSync
{
public:
  using ScanImuPolicy =
      message_filters::sync_policies::ApproximateTime<sensor_msgs::LaserScan, sensor_msgs::Imu>;

  explicit StereoSync(ros::NodeHandle& nh)
    : left_sub_(nh, "stereo/left/image_raw", 5),
      right_sub_(nh, "stereo/right/image_raw", 5),
      stereo_sync_(left_sub_, right_sub_, 10),
      scan_sub_(nh, "scan", 10),
      imu_sub_(nh, "imu/data", 50),
      scan_imu_sync_(ScanImuPolicy(20), scan_sub_, imu_sub_)
  {
    side_by_side_pub_ = nh.advertise<sensor_msgs::Image>("stereo/side_by_side", 2);
    leveled_scan_pub_ = nh.advertise<sensor_msgs::LaserScan>("scan_leveled", 10);

    // TimeSynchronizer::registerCallback with boost::bind.
    stereo_sync_.registerCallback(boost::bind(&StereoSync::onStereoPair, this, _1, _2));
    // Synchronizer<ApproximateTime>::registerCallback with member function pointer + this.
    scan_imu_sync_.registerCallback(&StereoSync::onScanImu, this);
  }

  void onStereoPair(const sensor_msgs::ImageConstPtr& left, const sensor_msgs::ImageConstPtr& right)
  {
    if (left->height != right->height || left->encoding != right->encoding)
    {
      ROS_WARN_THROTTLE(5.0, "stereo_sync: left/right images differ in shape");
      return;
    }
    sensor_msgs::Image out;
    out.header = left->header;
    out.height = left->height;
    out.width = left->width + right->width;
    out.encoding = left->encoding;
    out.step = left->step + right->step;
    out.data.resize(out.step * out.height);
    for (uint32_t row = 0; row < out.height; ++row)
    {
      std::copy_n(&left->data[row * left->step], left->step, &out.data[row * out.step]);
      std::copy_n(&right->data[row * right->step], right->step,
                  &out.data[row * out.step + left->step]);
    }
    // EXPECT stereo/side_by_side: dependent, none (synchronizer callback).
    side_by_side_pub_.publish(out);
  }

  void onScanImu(const sensor_msgs::LaserScanConstPtr& scan, const sensor_msgs::ImuConstPtr& imu)
  {
    // Roll of the platform from the IMU quaternion; drop the scan when tilted too much.
    const auto& q = imu->orientation;
    const double roll = std::atan2(2.0 * (q.w * q.x + q.y * q.z), 1.0 - 2.0 * (q.x * q.x + q.y * q.y));
    if (std::fabs(roll) > 0.1)
    {
      return;
    }
    // EXPECT scan_leveled: dependent, none (synchronizer callback).
    leveled_scan_pub_.publish(*scan);
  }

private:
  message_filters::Subscriber<sensor_msgs::Image> left_sub_;
  message_filters::Subscriber<sensor_msgs::Image> right_sub_;
  message_filters::TimeSynchronizer<sensor_msgs::Image, sensor_msgs::Image> stereo_sync_;
  message_filters::Subscriber<sensor_msgs::LaserScan> scan_sub_;
  message_filters::Subscriber<sensor_msgs::Imu> imu_sub_;
  message_filters::Synchronizer<ScanImuPolicy> scan_imu_sync_;
  ros::Publisher side_by_side_pub_;
  ros::Publisher leveled_scan_pub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "stereo_sync");
  ros::NodeHandle nh;
  StereoSync sync(nh);
  ros::spin();
  return 0;
}
