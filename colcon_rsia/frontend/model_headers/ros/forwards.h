// colcon-rsia model of <ros/forwards.h>: forward declarations, pointer
// typedefs, the timer event structs and the callback typedefs.
#ifndef RSIA_MODEL_ROS_FORWARDS_H
#define RSIA_MODEL_ROS_FORWARDS_H

#include <list>
#include <set>
#include <string>
#include <vector>

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/datatypes.h>
#include <ros/exceptions.h>
#include <ros/macros.h>
#include <ros/time.h>

namespace ros
{

typedef boost::shared_ptr<void> VoidPtr;
typedef boost::weak_ptr<void> VoidWPtr;
typedef boost::shared_ptr<void const> VoidConstPtr;
typedef boost::weak_ptr<void const> VoidConstWPtr;

class Header;
class Transport;
class Connection;
class Publication;
class Subscription;
class ServicePublication;
class NodeHandle;
class SingleSubscriberPublisher;
class Publisher;
class Subscriber;
class ServiceServer;
class ServiceClient;
class Timer;
class WallTimer;
class SteadyTimer;
class CallbackQueue;
class CallbackQueueInterface;
class CallbackInterface;
class Spinner;
class TransportHints;
struct SubscribeOptions;
struct AdvertiseOptions;
struct AdvertiseServiceOptions;
struct ServiceClientOptions;
struct TimerOptions;
struct WallTimerOptions;
struct SteadyTimerOptions;

typedef boost::shared_ptr<NodeHandle> NodeHandlePtr;
typedef boost::shared_ptr<CallbackInterface> CallbackInterfacePtr;
typedef boost::shared_ptr<Connection> ConnectionPtr;
typedef boost::shared_ptr<Publication> PublicationPtr;
typedef boost::shared_ptr<Subscription> SubscriptionPtr;

typedef boost::function<void(const SingleSubscriberPublisher&)> SubscriberStatusCallback;

// passed to the callback of a ros::Timer
struct TimerEvent
{
  Time last_expected;
  Time last_real;
  Time last_expired;
  Time current_expected;
  Time current_real;
  Time current_expired;

  struct
  {
    WallDuration last_duration;
  } profile;
};
typedef boost::function<void(const TimerEvent&)> TimerCallback;

// passed to the callback of a ros::WallTimer
struct WallTimerEvent
{
  WallTime last_expected;
  WallTime last_real;
  WallTime last_expired;
  WallTime current_expected;
  WallTime current_real;
  WallTime current_expired;

  struct
  {
    WallDuration last_duration;
  } profile;
};
typedef boost::function<void(const WallTimerEvent&)> WallTimerCallback;

// passed to the callback of a ros::SteadyTimer
struct SteadyTimerEvent
{
  SteadyTime last_expected;
  SteadyTime last_real;
  SteadyTime last_expired;
  SteadyTime current_expected;
  SteadyTime current_real;
  SteadyTime current_expired;

  struct
  {
    WallDuration last_duration;
  } profile;
};
typedef boost::function<void(const SteadyTimerEvent&)> SteadyTimerCallback;

}  // namespace ros

#endif  // RSIA_MODEL_ROS_FORWARDS_H
