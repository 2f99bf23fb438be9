// colcon-rsia model of <tf2_geometry_msgs/tf2_geometry_msgs.h> (ROS 1; the
// ROS 2 header is <tf2_geometry_msgs/tf2_geometry_msgs.hpp>): conversions
// between geometry_msgs messages and the tf2 LinearMath types, and
// doTransform for stamped messages. It publishes nothing; it is modelled so
// that code using it parses and keeps the tf2 classes (a Quaternion stays a
// Quaternion, with its operators).
//
// The real header has one toMsg/fromMsg/doTransform overload per pair of
// types; the templates of <tf2/convert.h> stand for all of them.
#ifndef RSIA_MODEL_TF2_GEOMETRY_MSGS_H
#define RSIA_MODEL_TF2_GEOMETRY_MSGS_H

#include <rsia_model/message.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Transform.h>
#include <tf2/LinearMath/Vector3.h>
#include <tf2/convert.h>

#endif  // RSIA_MODEL_TF2_GEOMETRY_MSGS_H
