// colcon-rsia model of <tf2/utils.h>: yaw and Euler angles of any tf2 or
// geometry_msgs rotation, and the identity transform.
#ifndef RSIA_MODEL_TF2_UTILS_H
#define RSIA_MODEL_TF2_UTILS_H

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Transform.h>

namespace tf2
{

template <class A>
double getYaw(const A& a);
template <class A>
void getEulerYPR(const A& a, double& yaw, double& pitch, double& roll);
template <class A>
A getTransformIdentity();

}  // namespace tf2

#endif  // RSIA_MODEL_TF2_UTILS_H
