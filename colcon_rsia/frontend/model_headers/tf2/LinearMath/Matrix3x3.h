// colcon-rsia model of <tf2/LinearMath/Matrix3x3.h>.
#ifndef RSIA_MODEL_TF2_LINEARMATH_MATRIX3X3_H
#define RSIA_MODEL_TF2_LINEARMATH_MATRIX3X3_H

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Vector3.h>

namespace tf2
{

class Matrix3x3
{
public:
  Matrix3x3();
  explicit Matrix3x3(const Quaternion& q);
  Matrix3x3(const tf2Scalar& xx, const tf2Scalar& xy, const tf2Scalar& xz, const tf2Scalar& yx, const tf2Scalar& yy, const tf2Scalar& yz,
            const tf2Scalar& zx, const tf2Scalar& zy, const tf2Scalar& zz);
  Matrix3x3(const Matrix3x3& other);
  Matrix3x3& operator=(const Matrix3x3& other);

  Vector3 getColumn(int i) const;
  const Vector3& getRow(int i) const;
  Vector3& operator[](int i);
  const Vector3& operator[](int i) const;
  Matrix3x3& operator*=(const Matrix3x3& m);
  void setFromOpenGLSubMatrix(const tf2Scalar* m);
  void setValue(const tf2Scalar& xx, const tf2Scalar& xy, const tf2Scalar& xz, const tf2Scalar& yx, const tf2Scalar& yy, const tf2Scalar& yz,
                const tf2Scalar& zx, const tf2Scalar& zy, const tf2Scalar& zz);
  void setRotation(const Quaternion& q);
  void setEulerYPR(const tf2Scalar& yaw, const tf2Scalar& pitch, const tf2Scalar& roll);
  void setEulerZYX(tf2Scalar eulerZ, tf2Scalar eulerY, tf2Scalar eulerX);
  void setRPY(tf2Scalar roll, tf2Scalar pitch, tf2Scalar yaw);
  void setIdentity();
  static const Matrix3x3& getIdentity();
  void getOpenGLSubMatrix(tf2Scalar* m) const;
  void getRotation(Quaternion& q) const;
  void getEulerYPR(tf2Scalar& yaw, tf2Scalar& pitch, tf2Scalar& roll, unsigned int solution_number = 1) const;
  void getEulerZYX(tf2Scalar& yaw, tf2Scalar& pitch, tf2Scalar& roll, unsigned int solution_number = 1) const;
  void getRPY(tf2Scalar& roll, tf2Scalar& pitch, tf2Scalar& yaw, unsigned int solution_number = 1) const;
  Matrix3x3 scaled(const Vector3& s) const;
  tf2Scalar determinant() const;
  Matrix3x3 adjoint() const;
  Matrix3x3 absolute() const;
  Matrix3x3 transpose() const;
  Matrix3x3 inverse() const;
  Matrix3x3 transposeTimes(const Matrix3x3& m) const;
  Matrix3x3 timesTranspose(const Matrix3x3& m) const;
  tf2Scalar tdotx(const Vector3& v) const;
  tf2Scalar tdoty(const Vector3& v) const;
  tf2Scalar tdotz(const Vector3& v) const;
};

Vector3 operator*(const Matrix3x3& m, const Vector3& v);
Vector3 operator*(const Vector3& v, const Matrix3x3& m);
Matrix3x3 operator*(const Matrix3x3& m1, const Matrix3x3& m2);
bool operator==(const Matrix3x3& m1, const Matrix3x3& m2);

}  // namespace tf2

#endif  // RSIA_MODEL_TF2_LINEARMATH_MATRIX3X3_H
