// colcon-rsia model of <tf2/convert.h>: the conversion function templates
// (their specialisations live in packages such as tf2_geometry_msgs).
#ifndef RSIA_MODEL_TF2_CONVERT_H
#define RSIA_MODEL_TF2_CONVERT_H

#include <string>

#include <rsia_model/message.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>
#include <tf2/exceptions.h>
#include <tf2/transform_datatypes.h>

namespace tf2
{

template <class T>
void doTransform(const T& data_in, T& data_out, const geometry_msgs::TransformStamped& transform);
template <class T>
const ros::Time& getTimestamp(const T& t);
template <class T>
const std::string& getFrameId(const T& t);
template <class A, class B>
B toMsg(const A& a);
// The overloads of tf2_geometry_msgs and the like (ROS 1 and ROS 2), which
// code also reaches through headers the model lacks: one template each,
// with a one-argument toMsg returning a catch-all value that converts to
// any message.
template <class A>
::rsia_model::Any toMsg(const A& in);
template <class A, class B>
B& toMsg(const A& in, B& out);
template <class A, class B, class C>
void doTransform(const A& in, B& out, const C& transform);
template <class A, class B>
void fromMsg(const A& a, B& b);
template <class A, class B>
void convert(const A& a, B& b);
template <class A>
void convert(const A& a1, A& a2);

}  // namespace tf2

#endif  // RSIA_MODEL_TF2_CONVERT_H
