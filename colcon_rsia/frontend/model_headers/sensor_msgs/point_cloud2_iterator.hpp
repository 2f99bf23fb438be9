// colcon-rsia model of <sensor_msgs/point_cloud2_iterator.hpp> (ROS 2): the
// typed iterators over a PointCloud2's fields and its modifier (not
// messages: a hand-written header of sensor_msgs).
#ifndef RSIA_MODEL_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_HPP
#define RSIA_MODEL_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_HPP

#include <cstddef>
#include <string>

#include <sensor_msgs/msg/point_cloud2.hpp>

#define RSIA_MODEL_POINT_CLOUD2_CLOUD sensor_msgs::msg::PointCloud2
#include <rsia_model/point_cloud2_iterator.h>
#undef RSIA_MODEL_POINT_CLOUD2_CLOUD

#endif  // RSIA_MODEL_SENSOR_MSGS_POINT_CLOUD2_ITERATOR_HPP
