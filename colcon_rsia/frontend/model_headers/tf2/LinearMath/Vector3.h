// colcon-rsia model of <tf2/LinearMath/Vector3.h>.
#ifndef RSIA_MODEL_TF2_LINEARMATH_VECTOR3_H
#define RSIA_MODEL_TF2_LINEARMATH_VECTOR3_H

#include <tf2/LinearMath/Scalar.h>

namespace tf2
{

class Vector3
{
public:
  tf2Scalar m_floats[4];

  Vector3();
  Vector3(const tf2Scalar& x, const tf2Scalar& y, const tf2Scalar& z);

  Vector3& operator+=(const Vector3& v);
  Vector3& operator-=(const Vector3& v);
  Vector3& operator*=(const tf2Scalar& s);
  Vector3& operator/=(const tf2Scalar& s);
  tf2Scalar dot(const Vector3& v) const;
  tf2Scalar length2() const;
  tf2Scalar length() const;
  tf2Scalar distance2(const Vector3& v) const;
  tf2Scalar distance(const Vector3& v) const;
  Vector3& normalize();
  Vector3 normalized() const;
  Vector3 rotate(const Vector3& wAxis, const tf2Scalar angle) const;
  tf2Scalar angle(const Vector3& v) const;
  Vector3 absolute() const;
  Vector3 cross(const Vector3& v) const;
  tf2Scalar triple(const Vector3& v1, const Vector3& v2) const;
  int minAxis() const;
  int maxAxis() const;
  Vector3 lerp(const Vector3& v, const tf2Scalar& t) const;
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
  bool operator==(const Vector3& other) const;
  bool operator!=(const Vector3& other) const;
  void setMax(const Vector3& other);
  void setMin(const Vector3& other);
  void setValue(const tf2Scalar& x, const tf2Scalar& y, const tf2Scalar& z);
  void setZero();
  bool isZero() const;
  bool fuzzyZero() const;
};

Vector3 operator+(const Vector3& v1, const Vector3& v2);
Vector3 operator*(const Vector3& v1, const Vector3& v2);
Vector3 operator-(const Vector3& v1, const Vector3& v2);
Vector3 operator-(const Vector3& v);
Vector3 operator*(const Vector3& v, const tf2Scalar& s);
Vector3 operator*(const tf2Scalar& s, const Vector3& v);
Vector3 operator/(const Vector3& v, const tf2Scalar& s);
Vector3 operator/(const Vector3& v1, const Vector3& v2);
tf2Scalar tf2Dot(const Vector3& v1, const Vector3& v2);
tf2Scalar tf2Distance(const Vector3& v1, const Vector3& v2);
Vector3 tf2Cross(const Vector3& v1, const Vector3& v2);

}  // namespace tf2

#endif  // RSIA_MODEL_TF2_LINEARMATH_VECTOR3_H
