// colcon-rsia model of <tf2/LinearMath/Transform.h>.
#ifndef RSIA_MODEL_TF2_LINEARMATH_TRANSFORM_H
#define RSIA_MODEL_TF2_LINEARMATH_TRANSFORM_H

#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Vector3.h>

namespace tf2
{

class Transform
{
public:
  Transform();
  explicit Transform(const Quaternion& q, const Vector3& c = Vector3(tf2Scalar(0), tf2Scalar(0), tf2Scalar(0)));
  explicit Transform(const Matrix3x3& b, const Vector3& c = Vector3(tf2Scalar(0), tf2Scalar(0), tf2Scalar(0)));
  Transform(const Transform& other);
  Transform& operator=(const Transform& other);

  void mult(const Transform& t1, const Transform& t2);
  Vector3 operator()(const Vector3& x) const;
  Vector3 operator*(const Vector3& x) const;
  Quaternion operator*(const Quaternion& q) const;
  Matrix3x3& getBasis();
  const Matrix3x3& getBasis() const;
  Vector3& getOrigin();
  const Vector3& getOrigin() const;
  Quaternion getRotation() const;
  void setFromOpenGLMatrix(const tf2Scalar* m);
  void getOpenGLMatrix(tf2Scalar* m) const;
  void setOrigin(const Vector3& origin);
  Vector3 invXform(const Vector3& inVec) const;
  void setBasis(const Matrix3x3& basis);
  void setRotation(const Quaternion& q);
  void setIdentity();
  Transform& operator*=(const Transform& t);
  Transform inverse() const;
  Transform inverseTimes(const Transform& t) const;
  Transform operator*(const Transform& t) const;
  static const Transform& getIdentity();
};

bool operator==(const Transform& t1, const Transform& t2);

}  // namespace tf2

#endif  // RSIA_MODEL_TF2_LINEARMATH_TRANSFORM_H
