// colcon-rsia model of <ros/node_handle.h>: ros::NodeHandle.
//
// Every overload set is complete (advertise 3, subscribe 13, advertiseService
// 9, serviceClient 3, createTimer 6, createWallTimer 4, createSteadyTimer 4)
// so that a user call resolves to the equivalent declaration; default
// arguments and parameter passing (by value / reference) follow roscpp.
#ifndef RSIA_MODEL_ROS_NODE_HANDLE_H
#define RSIA_MODEL_ROS_NODE_HANDLE_H

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <boost/bind/bind.hpp>
#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <ros/advertise_options.h>
#include <ros/advertise_service_options.h>
#include <ros/common.h>
#include <ros/forwards.h>
#include <ros/init.h>
#include <ros/message_event.h>
#include <ros/publisher.h>
#include <ros/rate.h>
#include <ros/service_callback_helper.h>
#include <ros/service_client.h>
#include <ros/service_client_options.h>
#include <ros/service_server.h>
#include <ros/spinner.h>
#include <ros/steady_timer.h>
#include <ros/steady_timer_options.h>
#include <ros/subscribe_options.h>
#include <ros/subscriber.h>
#include <ros/timer.h>
#include <ros/timer_options.h>
#include <ros/transport_hints.h>
#include <ros/wall_timer.h>
#include <ros/wall_timer_options.h>
#include <xmlrpcpp/XmlRpcValue.h>

namespace ros
{

class NodeHandle
{
public:
  NodeHandle(const std::string& ns = std::string(), const M_string& remappings = M_string());
  NodeHandle(const NodeHandle& rhs);
  NodeHandle(const NodeHandle& parent, const std::string& ns);
  NodeHandle(const NodeHandle& parent, const std::string& ns, const M_string& remappings);
  ~NodeHandle();

  NodeHandle& operator=(const NodeHandle& rhs);

  void setCallbackQueue(CallbackQueueInterface* queue);
  CallbackQueueInterface* getCallbackQueue() const;
  const std::string& getNamespace() const;
  const std::string& getUnresolvedNamespace() const;
  std::string resolveName(const std::string& name, bool remap = true) const;

  // --- publishers ---------------------------------------------------------

  template <class M>
  Publisher advertise(const std::string& topic, uint32_t queue_size, bool latch = false);

  template <class M>
  Publisher advertise(const std::string& topic, uint32_t queue_size,
                      const SubscriberStatusCallback& connect_cb,
                      const SubscriberStatusCallback& disconnect_cb = SubscriberStatusCallback(),
                      const VoidConstPtr& tracked_object = VoidConstPtr(), bool latch = false);

  Publisher advertise(AdvertiseOptions& ops);

  // --- subscribers --------------------------------------------------------

  // 1, 2: member function taking M (the callback parameter type), T* object
  template <class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size, void (T::*fp)(M), T* obj,
                       const TransportHints& transport_hints = TransportHints());
  template <class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size, void (T::*fp)(M) const, T* obj,
                       const TransportHints& transport_hints = TransportHints());

  // 3, 4: member function taking the message's const shared pointer, T* object
  template <class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       void (T::*fp)(const boost::shared_ptr<M const>&), T* obj,
                       const TransportHints& transport_hints = TransportHints());
  template <class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       void (T::*fp)(const boost::shared_ptr<M const>&) const, T* obj,
                       const TransportHints& transport_hints = TransportHints());

  // 5, 6: member function taking M, shared pointer object
  template <class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size, void (T::*fp)(M),
                       const boost::shared_ptr<T>& obj,
                       const TransportHints& transport_hints = TransportHints());
  template <class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size, void (T::*fp)(M) const,
                       const boost::shared_ptr<T>& obj,
                       const TransportHints& transport_hints = TransportHints());

  // 7, 8: member function taking the const shared pointer, shared pointer object
  template <class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       void (T::*fp)(const boost::shared_ptr<M const>&), const boost::shared_ptr<T>& obj,
                       const TransportHints& transport_hints = TransportHints());
  template <class M, class T>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       void (T::*fp)(const boost::shared_ptr<M const>&) const,
                       const boost::shared_ptr<T>& obj,
                       const TransportHints& transport_hints = TransportHints());

  // 9, 10: free functions
  template <class M>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size, void (*fp)(M),
                       const TransportHints& transport_hints = TransportHints());
  template <class M>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       void (*fp)(const boost::shared_ptr<M const>&),
                       const TransportHints& transport_hints = TransportHints());

  // 11, 12: boost::function (lambdas, functors, boost::bind: M is explicit)
  template <class M>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       const boost::function<void(const boost::shared_ptr<M const>&)>& callback,
                       const VoidConstPtr& tracked_object = VoidConstPtr(),
                       const TransportHints& transport_hints = TransportHints());
  template <class M, class C>
  Subscriber subscribe(const std::string& topic, uint32_t queue_size,
                       const boost::function<void(C)>& callback,
                       const VoidConstPtr& tracked_object = VoidConstPtr(),
                       const TransportHints& transport_hints = TransportHints());

  // 13: options
  Subscriber subscribe(SubscribeOptions& ops);

  // --- services -----------------------------------------------------------

  template <class T, class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service, bool (T::*srv_func)(MReq&, MRes&), T* obj);
  template <class T, class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service,
                                 bool (T::*srv_func)(ServiceEvent<MReq, MRes>&), T* obj);
  template <class T, class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service, bool (T::*srv_func)(MReq&, MRes&),
                                 const boost::shared_ptr<T>& obj);
  template <class T, class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service,
                                 bool (T::*srv_func)(ServiceEvent<MReq, MRes>&),
                                 const boost::shared_ptr<T>& obj);
  template <class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service, bool (*srv_func)(MReq&, MRes&));
  template <class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service, bool (*srv_func)(ServiceEvent<MReq, MRes>&));
  template <class MReq, class MRes>
  ServiceServer advertiseService(const std::string& service,
                                 const boost::function<bool(MReq&, MRes&)>& callback,
                                 const VoidConstPtr& tracked_object = VoidConstPtr());
  template <class S>
  ServiceServer advertiseService(const std::string& service, const boost::function<bool(S&)>& callback,
                                 const VoidConstPtr& tracked_object = VoidConstPtr());
  ServiceServer advertiseService(AdvertiseServiceOptions& ops);

  template <class MReq, class MRes>
  ServiceClient serviceClient(const std::string& service_name, bool persistent = false,
                              const M_string& header_values = M_string());
  template <class Service>
  ServiceClient serviceClient(const std::string& service_name, bool persistent = false,
                              const M_string& header_values = M_string());
  ServiceClient serviceClient(ServiceClientOptions& ops);

  // --- timers -------------------------------------------------------------

  // a bare number is a ros::Rate (implicit): Hz
  template <class Handler, class Obj>
  Timer createTimer(Rate r, Handler h, Obj o, bool oneshot = false, bool autostart = true) const;
  template <class T>
  Timer createTimer(Duration period, void (T::*callback)(const TimerEvent&) const, T* obj,
                    bool oneshot = false, bool autostart = true) const;
  template <class T>
  Timer createTimer(Duration period, void (T::*callback)(const TimerEvent&), T* obj,
                    bool oneshot = false, bool autostart = true) const;
  template <class T>
  Timer createTimer(Duration period, void (T::*callback)(const TimerEvent&),
                    const boost::shared_ptr<T>& obj, bool oneshot = false, bool autostart = true) const;
  Timer createTimer(Duration period, const TimerCallback& callback, bool oneshot = false,
                    bool autostart = true) const;
  Timer createTimer(TimerOptions& ops) const;

  template <class T>
  WallTimer createWallTimer(WallDuration period, void (T::*callback)(const WallTimerEvent&), T* obj,
                            bool oneshot = false, bool autostart = true) const;
  template <class T>
  WallTimer createWallTimer(WallDuration period, void (T::*callback)(const WallTimerEvent&),
                            const boost::shared_ptr<T>& obj, bool oneshot = false,
                            bool autostart = true) const;
  WallTimer createWallTimer(WallDuration period, const WallTimerCallback& callback, bool oneshot = false,
                            bool autostart = true) const;
  WallTimer createWallTimer(WallTimerOptions& ops) const;

  template <class T>
  SteadyTimer createSteadyTimer(WallDuration period, void (T::*callback)(const SteadyTimerEvent&),
                                T* obj, bool oneshot = false, bool autostart = true) const;
  template <class T>
  SteadyTimer createSteadyTimer(WallDuration period, void (T::*callback)(const SteadyTimerEvent&),
                                const boost::shared_ptr<T>& obj, bool oneshot = false,
                                bool autostart = true) const;
  SteadyTimer createSteadyTimer(WallDuration period, const SteadyTimerCallback& callback,
                                bool oneshot = false, bool autostart = true) const;
  SteadyTimer createSteadyTimer(SteadyTimerOptions& ops) const;

  // --- parameters ---------------------------------------------------------

  void setParam(const std::string& key, const XmlRpc::XmlRpcValue& v) const;
  void setParam(const std::string& key, const std::string& s) const;
  void setParam(const std::string& key, const char* s) const;
  void setParam(const std::string& key, double d) const;
  void setParam(const std::string& key, int i) const;
  void setParam(const std::string& key, bool b) const;
  void setParam(const std::string& key, const std::vector<std::string>& vec) const;
  void setParam(const std::string& key, const std::vector<double>& vec) const;
  void setParam(const std::string& key, const std::vector<float>& vec) const;
  void setParam(const std::string& key, const std::vector<int>& vec) const;
  void setParam(const std::string& key, const std::vector<bool>& vec) const;
  void setParam(const std::string& key, const std::map<std::string, std::string>& map) const;
  void setParam(const std::string& key, const std::map<std::string, double>& map) const;
  void setParam(const std::string& key, const std::map<std::string, float>& map) const;
  void setParam(const std::string& key, const std::map<std::string, int>& map) const;
  void setParam(const std::string& key, const std::map<std::string, bool>& map) const;

  bool getParam(const std::string& key, std::string& s) const;
  bool getParam(const std::string& key, double& d) const;
  bool getParam(const std::string& key, float& f) const;
  bool getParam(const std::string& key, int& i) const;
  bool getParam(const std::string& key, bool& b) const;
  bool getParam(const std::string& key, XmlRpc::XmlRpcValue& v) const;
  bool getParam(const std::string& key, std::vector<std::string>& vec) const;
  bool getParam(const std::string& key, std::vector<double>& vec) const;
  bool getParam(const std::string& key, std::vector<float>& vec) const;
  bool getParam(const std::string& key, std::vector<int>& vec) const;
  bool getParam(const std::string& key, std::vector<bool>& vec) const;
  bool getParam(const std::string& key, std::map<std::string, std::string>& map) const;
  bool getParam(const std::string& key, std::map<std::string, double>& map) const;
  bool getParam(const std::string& key, std::map<std::string, float>& map) const;
  bool getParam(const std::string& key, std::map<std::string, int>& map) const;
  bool getParam(const std::string& key, std::map<std::string, bool>& map) const;

  bool getParamCached(const std::string& key, std::string& s) const;
  bool getParamCached(const std::string& key, double& d) const;
  bool getParamCached(const std::string& key, float& f) const;
  bool getParamCached(const std::string& key, int& i) const;
  bool getParamCached(const std::string& key, bool& b) const;
  bool getParamCached(const std::string& key, XmlRpc::XmlRpcValue& v) const;
  bool getParamCached(const std::string& key, std::vector<std::string>& vec) const;
  bool getParamCached(const std::string& key, std::vector<double>& vec) const;
  bool getParamCached(const std::string& key, std::vector<float>& vec) const;
  bool getParamCached(const std::string& key, std::vector<int>& vec) const;
  bool getParamCached(const std::string& key, std::vector<bool>& vec) const;
  bool getParamCached(const std::string& key, std::map<std::string, std::string>& map) const;
  bool getParamCached(const std::string& key, std::map<std::string, double>& map) const;
  bool getParamCached(const std::string& key, std::map<std::string, float>& map) const;
  bool getParamCached(const std::string& key, std::map<std::string, int>& map) const;
  bool getParamCached(const std::string& key, std::map<std::string, bool>& map) const;

  bool hasParam(const std::string& key) const;
  bool searchParam(const std::string& key, std::string& result) const;
  bool deleteParam(const std::string& key) const;
  bool getParamNames(std::vector<std::string>& keys) const;

  template <typename T>
  bool param(const std::string& param_name, T& param_val, const T& default_val) const;
  template <typename T>
  T param(const std::string& param_name, const T& default_val) const;

  // --- node state ---------------------------------------------------------

  void shutdown();
  bool ok() const;
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_NODE_HANDLE_H
