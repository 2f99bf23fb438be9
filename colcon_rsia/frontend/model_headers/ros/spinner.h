// colcon-rsia model of <ros/spinner.h>.
#ifndef RSIA_MODEL_ROS_SPINNER_H
#define RSIA_MODEL_ROS_SPINNER_H

#include <cstdint>

#include <boost/shared_ptr.hpp>
#include <ros/types.h>

namespace ros
{

class CallbackQueue;
class NodeHandle;

class Spinner
{
public:
  virtual ~Spinner();
  virtual void spin(CallbackQueue* queue = 0) = 0;
};

class SingleThreadedSpinner : public Spinner
{
public:
  virtual void spin(CallbackQueue* queue = 0);
};

class MultiThreadedSpinner : public Spinner
{
public:
  MultiThreadedSpinner(uint32_t thread_count = 0);
  virtual void spin(CallbackQueue* queue = 0);
};

class AsyncSpinner
{
public:
  AsyncSpinner(uint32_t thread_count);
  AsyncSpinner(uint32_t thread_count, CallbackQueue* queue);
  bool canStart();
  void start();
  void stop();
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_SPINNER_H
