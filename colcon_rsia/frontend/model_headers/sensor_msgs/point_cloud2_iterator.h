// colcon-rsia model of <sensor_msgs/point_cloud2_iterator.h> (ROS 1): see
// point_cloud2_iterator.hpp.
#ifndef RSIA_MODEL_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_H
#define RSIA_MODEL_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_H

#include <cstddef>
#include <string>

#include <sensor_msgs/PointCloud2.h>

#define RSIA_MODEL_POINT_CLOUD2_CLOUD sensor_msgs::PointCloud2
#include <rsia_model/point_cloud2_iterator.h>
#undef RSIA_MODEL_POINT_CLOUD2_CLOUD

#endif  // RSIA_MODEL_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_H
