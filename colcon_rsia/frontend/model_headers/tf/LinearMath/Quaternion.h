// colcon-rsia model of <tf/LinearMath/Quaternion.h>.
#ifndef RSIA_MODEL_TF_LINEARMATH_QUATERNION_H
#define RSIA_MODEL_TF_LINEARMATH_QUATERNION_H

#include <tf/LinearMath/Vector3.h>

namespace tf
{

class QuadWord
{
public:
  QuadWord();
  QuadWord(const tfScalar& x, const tfScalar& y, const tfScalar& z);
  QuadWord(const tfScalar& x, const tfScalar& y, const tfScalar& z, const tfScalar& w);

  const tfScalar& getX() const;
  const tfScalar& getY() const;
  const tfScalar& getZ() const;
  void setX(tfScalar x);
  void setY(tfScalar y);
  void setZ(tfScalar z);
  void setW(tfScalar w);
  const tfScalar& x() const;
  const tfScalar& y() const;
  const tfScalar& z() const;
  const tfScalar& w() const;
  operator tfScalar*();
  operator const tfScalar*() const;
  bool operator==(const QuadWord& other) const;
  bool operator!=(const QuadWord& other) const;
  void setValue(const tfScalar& x, const tfScalar& y, const tfScalar& z);
  void setValue(const tfScalar& x, const tfScalar& y, const tfScalar& z, const tfScalar& w);
};

class Quaternion : public QuadWord
{
public:
  Quaternion();
  Quaternion(const tfScalar& x, const tfScalar& y, const tfScalar& z, const tfScalar& w);
  Quaternion(const Vector3& axis, const tfScalar& angle);
  Quaternion(const tfScalar& yaw, const tfScalar& pitch, const tfScalar& roll);

  void setRotation(const Vector3& axis, const tfScalar& angle);
  void setEuler(const tfScalar& yaw, const tfScalar& pitch, const tfScalar& roll);
  void setRPY(const tfScalar& roll, const tfScalar& pitch, const tfScalar& yaw);
  void setEulerZYX(const tfScalar& yaw, const tfScalar& pitch, const tfScalar& roll);
  Quaternion& operator+=(const Quaternion& q);
  Quaternion& operator-=(const Quaternion& q);
  Quaternion& operator*=(const tfScalar& s);
  Quaternion& operator*=(const Quaternion& q);
  Quaternion& operator/=(const tfScalar& s);
  tfScalar dot(const Quaternion& q) const;
  tfScalar length2() const;
  tfScalar length() const;
  Quaternion& normalize();
  Quaternion normalized() const;
  tfScalar angle(const Quaternion& q) const;
  tfScalar angleShortestPath(const Quaternion& q) const;
  tfScalar getAngle() const;
  tfScalar getAngleShortestPath() const;
  Vector3 getAxis() const;
  Quaternion inverse() const;
  Quaternion operator+(const Quaternion& q2) const;
  Quaternion operator-(const Quaternion& q2) const;
  Quaternion operator-() const;
  Quaternion operator*(const tfScalar& s) const;
  Quaternion operator/(const tfScalar& s) const;
  Quaternion farthest(const Quaternion& qd) const;
  Quaternion nearest(const Quaternion& qd) const;
  Quaternion slerp(const Quaternion& q, const tfScalar& t) const;
  static const Quaternion& getIdentity();
};

Quaternion operator*(const Quaternion& q1, const Quaternion& q2);
Quaternion operator*(const Quaternion& q, const Vector3& w);
Quaternion operator*(const Vector3& w, const Quaternion& q);
tfScalar dot(const Quaternion& q1, const Quaternion& q2);
tfScalar length(const Quaternion& q);
tfScalar angle(const Quaternion& q1, const Quaternion& q2);
tfScalar angleShortestPath(const Quaternion& q1, const Quaternion& q2);
Quaternion inverse(const Quaternion& q);
Quaternion slerp(const Quaternion& q1, const Quaternion& q2, const tfScalar& t);
Vector3 quatRotate(const Quaternion& rotation, const Vector3& v);
Quaternion shortestArcQuat(const Vector3& v0, const Vector3& v1);
Quaternion shortestArcQuatNormalize2(Vector3& v0, Vector3& v1);

}  // namespace tf

#endif  // RSIA_MODEL_TF_LINEARMATH_QUATERNION_H
