// colcon-rsia model of <message_filters/synchronizer.h>: Synchronizer<Policy>
// (derives from its policy), fed by 2..9 filters, with registerCallback.
//
// ROS 1 and ROS 2 share this include name. Model mode defines
// RSIA_MODEL_RCLCPP for a ROS 2 unit (one including rclcpp or a ROS 2
// interface header); then the ROS 2 class is declared, else the ROS 1 one.
// The ROS 2 class is in <message_filters/synchronizer.hpp>; both define
// RSIA_MODEL_MESSAGE_FILTERS_SYNCHRONIZER.
#ifdef RSIA_MODEL_RCLCPP
#include <message_filters/synchronizer.hpp>
#else  // ROS 1
#ifndef RSIA_MODEL_MESSAGE_FILTERS_SYNCHRONIZER
#define RSIA_MODEL_MESSAGE_FILTERS_SYNCHRONIZER

#include <string>

#include <boost/bind/bind.hpp>
#include <boost/function.hpp>
#include <boost/noncopyable.hpp>
#include <boost/shared_ptr.hpp>
#include <message_filters/connection.h>
#include <message_filters/null_types.h>
#include <ros/message_event.h>

namespace message_filters
{

template <class Policy>
class Synchronizer : public boost::noncopyable, public Policy
{
public:
  typedef typename Policy::M0Event M0Event;
  typedef typename Policy::M1Event M1Event;

  template <class F0, class F1>
  Synchronizer(F0& f0, F1& f1);
  template <class F0, class F1, class F2>
  Synchronizer(F0& f0, F1& f1, F2& f2);
  template <class F0, class F1, class F2, class F3>
  Synchronizer(F0& f0, F1& f1, F2& f2, F3& f3);
  template <class F0, class F1, class F2, class F3, class F4>
  Synchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4);
  template <class F0, class F1, class F2, class F3, class F4, class F5>
  Synchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6>
  Synchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6, class F7>
  Synchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6, F7& f7);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6, class F7, class F8>
  Synchronizer(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6, F7& f7, F8& f8);
  Synchronizer();
  template <class F0, class F1>
  Synchronizer(const Policy& policy, F0& f0, F1& f1);
  template <class F0, class F1, class F2>
  Synchronizer(const Policy& policy, F0& f0, F1& f1, F2& f2);
  template <class F0, class F1, class F2, class F3>
  Synchronizer(const Policy& policy, F0& f0, F1& f1, F2& f2, F3& f3);
  template <class F0, class F1, class F2, class F3, class F4>
  Synchronizer(const Policy& policy, F0& f0, F1& f1, F2& f2, F3& f3, F4& f4);
  template <class F0, class F1, class F2, class F3, class F4, class F5>
  Synchronizer(const Policy& policy, F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6>
  Synchronizer(const Policy& policy, F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6, class F7>
  Synchronizer(const Policy& policy, F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6, F7& f7);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6, class F7, class F8>
  Synchronizer(const Policy& policy, F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6, F7& f7, F8& f8);
  Synchronizer(const Policy& policy);
  ~Synchronizer();

  void init();

  template <class F0, class F1>
  void connectInput(F0& f0, F1& f1);
  template <class F0, class F1, class F2>
  void connectInput(F0& f0, F1& f1, F2& f2);
  template <class F0, class F1, class F2, class F3>
  void connectInput(F0& f0, F1& f1, F2& f2, F3& f3);
  template <class F0, class F1, class F2, class F3, class F4>
  void connectInput(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4);
  template <class F0, class F1, class F2, class F3, class F4, class F5>
  void connectInput(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6>
  void connectInput(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6, class F7>
  void connectInput(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6, F7& f7);
  template <class F0, class F1, class F2, class F3, class F4, class F5, class F6, class F7, class F8>
  void connectInput(F0& f0, F1& f1, F2& f2, F3& f3, F4& f4, F5& f5, F6& f6, F7& f7, F8& f8);

  template <class C>
  Connection registerCallback(C& callback);
  template <class C>
  Connection registerCallback(const C& callback);
  template <class C, typename T>
  Connection registerCallback(const C& callback, T* t);
  template <class C, typename T>
  Connection registerCallback(C& callback, T* t);

  template <int i, class E>
  void add(const E& msg_or_event);

  void setName(const std::string& name);
  const std::string& getName();
};

template <typename M0, typename M1, typename M2, typename M3, typename M4, typename M5, typename M6,
          typename M7, typename M8>
struct PolicyBase
{
  typedef ros::MessageEvent<M0 const> M0Event;
  typedef ros::MessageEvent<M1 const> M1Event;
  typedef ros::MessageEvent<M2 const> M2Event;
  typedef ros::MessageEvent<M3 const> M3Event;
  typedef ros::MessageEvent<M4 const> M4Event;
  typedef ros::MessageEvent<M5 const> M5Event;
  typedef ros::MessageEvent<M6 const> M6Event;
  typedef ros::MessageEvent<M7 const> M7Event;
  typedef ros::MessageEvent<M8 const> M8Event;
};

}  // namespace message_filters

#endif  // RSIA_MODEL_MESSAGE_FILTERS_SYNCHRONIZER
#endif  // RSIA_MODEL_RCLCPP
