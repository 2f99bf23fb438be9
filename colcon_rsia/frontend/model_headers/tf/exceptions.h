// colcon-rsia model of <tf/exceptions.h>: the tf exceptions are tf2's.
#ifndef RSIA_MODEL_TF_EXCEPTIONS_H
#define RSIA_MODEL_TF_EXCEPTIONS_H

#include <tf2/exceptions.h>

namespace tf
{

typedef tf2::TransformException TransformException;
typedef tf2::LookupException LookupException;
typedef tf2::ConnectivityException ConnectivityException;
typedef tf2::ExtrapolationException ExtrapolationException;
typedef tf2::InvalidArgumentException InvalidArgument;

}  // namespace tf

#endif  // RSIA_MODEL_TF_EXCEPTIONS_H
