// colcon-rsia model of <tf2/LinearMath/Scalar.h>.
#ifndef RSIA_MODEL_TF2_LINEARMATH_SCALAR_H
#define RSIA_MODEL_TF2_LINEARMATH_SCALAR_H

#include <rsia_model/std.h>

typedef double tf2Scalar;

#endif  // RSIA_MODEL_TF2_LINEARMATH_SCALAR_H
