// colcon-rsia model of <tf2/transform_datatypes.h>: tf2::Stamped<T>.
#ifndef RSIA_MODEL_TF2_TRANSFORM_DATATYPES_H
#define RSIA_MODEL_TF2_TRANSFORM_DATATYPES_H

#include <string>

#include <ros/time.h>

namespace tf2
{

template <typename T>
class Stamped : public T
{
public:
  ros::Time stamp_;
  std::string frame_id_;

  Stamped();
  Stamped(const T& input, const ros::Time& timestamp, const std::string& frame_id);
  Stamped(const Stamped<T>& s);
  void setData(const T& input);
};

template <typename T>
bool operator==(const Stamped<T>& a, const Stamped<T>& b);

}  // namespace tf2

#endif  // RSIA_MODEL_TF2_TRANSFORM_DATATYPES_H
