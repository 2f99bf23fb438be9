// colcon-rsia model of <tf/LinearMath/Matrix3x3.h>.
#ifndef RSIA_MODEL_TF_LINEARMATH_MATRIX3X3_H
#define RSIA_MODEL_TF_LINEARMATH_MATRIX3X3_H

#include <tf/LinearMath/Quaternion.h>
#include <tf/LinearMath/Vector3.h>

namespace tf
{

class Matrix3x3
{
public:
  Matrix3x3();
  explicit Matrix3x3(const Quaternion& q);
  Matrix3x3(const tfScalar& xx, const tfScalar& xy, const tfScalar& xz, const tfScalar& yx, const tfScalar& yy, const tfScalar& yz,
            const tfScalar& zx, const tfScalar& zy, const tfScalar& zz);
  Matrix3x3(const Matrix3x3& other);
  Matrix3x3& operator=(const Matrix3x3& other);

  Vector3 getColumn(int i) const;
  const Vector3& getRow(int i) const;
  Vector3& operator[](int i);
  const Vector3& operator[](int i) const;
  Matrix3x3& operator*=(const Matrix3x3& m);
  void setFromOpenGLSubMatrix(const tfScalar* m);
  void setValue(const tfScalar& xx, const tfScalar& xy, const tfScalar& xz, const tfScalar& yx, const tfScalar& yy, const tfScalar& yz,
                const tfScalar& zx, const tfScalar& zy, const tfScalar& zz);
  void setRotation(const Quaternion& q);
  void setEulerYPR(const tfScalar& yaw, const tfScalar& pitch, const tfScalar& roll);
  void setEulerZYX(tfScalar eulerZ, tfScalar eulerY, tfScalar eulerX);
  void setRPY(tfScalar roll, tfScalar pitch, tfScalar yaw);
  void setIdentity();
  static const Matrix3x3& getIdentity();
  void getOpenGLSubMatrix(tfScalar* m) const;
  void getRotation(Quaternion& q) const;
  void getEulerYPR(tfScalar& yaw, tfScalar& pitch, tfScalar& roll, unsigned int solution_number = 1) const;
  void getEulerZYX(tfScalar& yaw, tfScalar& pitch, tfScalar& roll, unsigned int solution_number = 1) const;
  void getRPY(tfScalar& roll, tfScalar& pitch, tfScalar& yaw, unsigned int solution_number = 1) const;
  Matrix3x3 scaled(const Vector3& s) const;
  tfScalar determinant() const;
  Matrix3x3 adjoint() const;
  Matrix3x3 absolute() const;
  Matrix3x3 transpose() const;
  Matrix3x3 inverse() const;
  Matrix3x3 transposeTimes(const Matrix3x3& m) const;
  Matrix3x3 timesTranspose(const Matrix3x3& m) const;
  tfScalar tdotx(const Vector3& v) const;
  tfScalar tdoty(const Vector3& v) const;
  tfScalar tdotz(const Vector3& v) const;
};

Vector3 operator*(const Matrix3x3& m, const Vector3& v);
Vector3 operator*(const Vector3& v, const Matrix3x3& m);
Matrix3x3 operator*(const Matrix3x3& m1, const Matrix3x3& m2);
bool operator==(const Matrix3x3& m1, const Matrix3x3& m2);

}  // namespace tf

#endif  // RSIA_MODEL_TF_LINEARMATH_MATRIX3X3_H
