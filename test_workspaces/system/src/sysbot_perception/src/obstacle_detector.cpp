// Obstacle detector: thresholds each /image frame and publishes the centroid
// of bright pixels as an obstacle on /obstacles, once per received frame.
// Expected: /obstacles dependent (none).
#include <ros/ros.h>
#include <geometry_msgs/PoseArray.h>
#include <sensor_msgs/Image.h>

namespace
{
ros::Publisher g_obstacle_pub;

void imageCallback(const sensor_msgs::Image::ConstPtr& img)
{
  geometry_msgs::PoseArray obstacles;
  obstacles.header = img->header;

  double sum_u = 0.0;
  double sum_v = 0.0;
  unsigned int hits = 0;
  for (unsigned int v = 0; v < img->height; ++v)
  {
    for (unsigned int u = 0; u < img->width; ++u)
    {
      if (img->data[v * img->step + u] > 200)
      {
        sum_u += u;
        sum_v += v;
        ++hits;
      }
    }
  }
  if (hits > 0)
  {
    geometry_msgs::Pose p;
    p.position.x = sum_u / hits;
    p.position.y = sum_v / hits;
    p.orientation.w = 1.0;
    obstacles.poses.push_back(p);
  }
  g_obstacle_pub.publish(obstacles);
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "obstacle_detector");
  ros::NodeHandle nh;
  g_obstacle_pub = nh.advertise<geometry_msgs::PoseArray>("obstacles", 5);
  ros::Subscriber image_sub = nh.subscribe("image", 2, imageCallback);
  ros::spin();
  return 0;
}
