// colcon-rsia model of <tf2/exceptions.h>.
#ifndef RSIA_MODEL_TF2_EXCEPTIONS_H
#define RSIA_MODEL_TF2_EXCEPTIONS_H

#include <stdexcept>
#include <string>

namespace tf2
{

class TransformException : public std::runtime_error
{
public:
  TransformException(const std::string errorDescription);
};

class ConnectivityException : public TransformException
{
public:
  ConnectivityException(const std::string errorDescription);
};

class LookupException : public TransformException
{
public:
  LookupException(const std::string errorDescription);
};

class ExtrapolationException : public TransformException
{
public:
  ExtrapolationException(const std::string errorDescription);
};

class InvalidArgumentException : public TransformException
{
public:
  InvalidArgumentException(const std::string errorDescription);
};

class TimeoutException : public TransformException
{
public:
  TimeoutException(const std::string errorDescription);
};

}  // namespace tf2

#endif  // RSIA_MODEL_TF2_EXCEPTIONS_H
