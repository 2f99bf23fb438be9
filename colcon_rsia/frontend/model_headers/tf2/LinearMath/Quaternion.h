// colcon-rsia model of <tf2/LinearMath/Quaternion.h>.
#ifndef RSIA_MODEL_TF2_LINEARMATH_QUATERNION_H
#define RSIA_MODEL_TF2_LINEARMATH_QUATERNION_H

#include <tf2/LinearMath/Vector3.h>

namespace tf2
{

class QuadWord
{
public:
  QuadWord();
  QuadWord(const tf2Scalar& x, const tf2Scalar& y, const tf2Scalar& z);
  QuadWord(const tf2Scalar& x, const tf2Scalar& y, const tf2Scalar& z, const tf2Scalar& w);

  const tf2Scalar& getX() const;
  const tf2Scalar& getY() const;
  const tf2Scalar& getZ() const;
  void setX(tf2Scalar x);
  void setY(tf2Scalar y);
  void setZ(tf2Scalar z);
  void setW(tf2Scalar w);
  const tf2Scalar& x() const;
  const tf2Scalar& y() const;
  const tf2Scalar& z() const;
  const tf2Scalar& w() const;
  operator tf2Scalar*();
  operator const tf2Scalar*() const;
  bool operator==(const QuadWord& other) const;
  bool operator!=(const QuadWord& other) const;
  void setValue(const tf2Scalar& x, const tf2Scalar& y, const tf2Scalar& z);
  void setValue(const tf2Scalar& x, const tf2Scalar& y, const tf2Scalar& z, const tf2Scalar& w);
};

class Quaternion : public QuadWord
{
public:
  Quaternion();
  Quaternion(const tf2Scalar& x, const tf2Scalar& y, const tf2Scalar& z, const tf2Scalar& w);
  Quaternion(const Vector3& axis, const tf2Scalar& angle);
  Quaternion(const tf2Scalar& yaw, const tf2Scalar& pitch, const tf2Scalar& roll);
  const tf2Scalar& getW() const;

  void setRotation(const Vector3& axis, const tf2Scalar& angle);
  void setEuler(const tf2Scalar& yaw, const tf2Scalar& pitch, const tf2Scalar& roll);
  void setRPY(const tf2Scalar& roll, const tf2Scalar& pitch, const tf2Scalar& yaw);
  void setEulerZYX(const tf2Scalar& yaw, const tf2Scalar& pitch, const tf2Scalar& roll);
  Quaternion& operator+=(const Quaternion& q);
  Quaternion& operator-=(const Quaternion& q);
  Quaternion& operator*=(const tf2Scalar& s);
  Quaternion& operator*=(const Quaternion& q);
  Quaternion& operator/=(const tf2Scalar& s);
  tf2Scalar dot(const Quaternion& q) const;
  tf2Scalar length2() const;
  tf2Scalar length() const;
  Quaternion& normalize();
  Quaternion normalized() const;
  tf2Scalar angle(const Quaternion& q) const;
  tf2Scalar angleShortestPath(const Quaternion& q) const;
  tf2Scalar getAngle() const;
  tf2Scalar getAngleShortestPath() const;
  Vector3 getAxis() const;
  Quaternion inverse() const;
  Quaternion operator+(const Quaternion& q2) const;
  Quaternion operator-(const Quaternion& q2) const;
  Quaternion operator-() const;
  Quaternion operator*(const tf2Scalar& s) const;
  Quaternion operator/(const tf2Scalar& s) const;
  Quaternion farthest(const Quaternion& qd) const;
  Quaternion nearest(const Quaternion& qd) const;
  Quaternion slerp(const Quaternion& q, const tf2Scalar& t) const;
  static const Quaternion& getIdentity();
};

Quaternion operator*(const Quaternion& q1, const Quaternion& q2);
Quaternion operator*(const Quaternion& q, const Vector3& w);
Quaternion operator*(const Vector3& w, const Quaternion& q);
tf2Scalar dot(const Quaternion& q1, const Quaternion& q2);
tf2Scalar length(const Quaternion& q);
tf2Scalar angle(const Quaternion& q1, const Quaternion& q2);
tf2Scalar angleShortestPath(const Quaternion& q1, const Quaternion& q2);
Quaternion inverse(const Quaternion& q);
Quaternion slerp(const Quaternion& q1, const Quaternion& q2, const tf2Scalar& t);
Vector3 quatRotate(const Quaternion& rotation, const Vector3& v);
Quaternion shortestArcQuat(const Vector3& v0, const Vector3& v1);
Quaternion shortestArcQuatNormalize2(Vector3& v0, Vector3& v1);

}  // namespace tf2

#endif  // RSIA_MODEL_TF2_LINEARMATH_QUATERNION_H
