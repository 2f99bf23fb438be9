// colcon-rsia model of <tf/LinearMath/Scalar.h>.
#ifndef RSIA_MODEL_TF_LINEARMATH_SCALAR_H
#define RSIA_MODEL_TF_LINEARMATH_SCALAR_H

#include <rsia_model/std.h>

typedef double tfScalar;

#endif  // RSIA_MODEL_TF_LINEARMATH_SCALAR_H
