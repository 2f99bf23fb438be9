// colcon-rsia model of <tf/LinearMath/Vector3.h>.
#ifndef RSIA_MODEL_TF_LINEARMATH_VECTOR3_H
#define RSIA_MODEL_TF_LINEARMATH_VECTOR3_H

#include <tf/LinearMath/Scalar.h>

namespace tf
{

class Vector3
{
public:
  tfScalar m_floats[4];

  Vector3();
  Vector3(const tfScalar& x, const tfScalar& y, const tfScalar& z);

  Vector3& operator+=(const Vector3& v);
  Vector3& operator-=(const Vector3& v);
  Vector3& operator*=(const tfScalar& s);
  Vector3& operator/=(const tfScalar& s);
  tfScalar dot(const Vector3& v) const;
  tfScalar length2() const;
  tfScalar length() const;
  tfScalar distance2(const Vector3& v) const;
  tfScalar distance(const Vector3& v) const;
  Vector3& normalize();
  Vector3 normalized() const;
  Vector3 rotate(const Vector3& wAxis, const tfScalar angle) const;
  tfScalar angle(const Vector3& v) const;
  Vector3 absolute() const;
  Vector3 cross(const Vector3& v) const;
  tfScalar triple(const Vector3& v1, const Vector3& v2) const;
  int minAxis() const;
  int maxAxis() const;
  Vector3 lerp(const Vector3& v, const tfScalar& t) const;
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
  bool operator==(const Vector3& other) const;
  bool operator!=(const Vector3& other) const;
  void setMax(const Vector3& other);
  void setMin(const Vector3& other);
  void setValue(const tfScalar& x, const tfScalar& y, const tfScalar& z);
  void setZero();
  bool isZero() const;
  bool fuzzyZero() const;
};

Vector3 operator+(const Vector3& v1, const Vector3& v2);
Vector3 operator*(const Vector3& v1, const Vector3& v2);
Vector3 operator-(const Vector3& v1, const Vector3& v2);
Vector3 operator-(const Vector3& v);
Vector3 operator*(const Vector3& v, const tfScalar& s);
Vector3 operator*(const tfScalar& s, const Vector3& v);
Vector3 operator/(const Vector3& v, const tfScalar& s);
Vector3 operator/(const Vector3& v1, const Vector3& v2);
tfScalar tfDot(const Vector3& v1, const Vector3& v2);
tfScalar tfDistance(const Vector3& v1, const Vector3& v2);
Vector3 tfCross(const Vector3& v1, const Vector3& v2);

}  // namespace tf

#endif  // RSIA_MODEL_TF_LINEARMATH_VECTOR3_H
