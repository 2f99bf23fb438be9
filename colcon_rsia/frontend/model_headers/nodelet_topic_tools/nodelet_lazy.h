// colcon-rsia model of <nodelet_topic_tools/nodelet_lazy.h>:
// nodelet_topic_tools::NodeletLazy, a nodelet base that advertises through
// advertise<M>(nh, topic, queue_size, latch) and calls the derived class's
// subscribe() when its first subscriber connects (unsubscribe() when the
// last leaves); its onInit makes nh_ and pnh_ (the nodelet's handle and
// its private one).
#ifndef RSIA_MODEL_NODELET_TOPIC_TOOLS_NODELET_LAZY_H
#define RSIA_MODEL_NODELET_TOPIC_TOOLS_NODELET_LAZY_H

#include <string>
#include <vector>

#include <boost/shared_ptr.hpp>
#include <boost/thread.hpp>
#include <nodelet/nodelet.h>
#include <ros/ros.h>

namespace nodelet_topic_tools
{

enum ConnectionStatus
{
  NOT_INITIALIZED,
  NOT_SUBSCRIBED,
  SUBSCRIBED
};

class NodeletLazy : public nodelet::Nodelet
{
public:
  NodeletLazy() {}

protected:
  virtual void onInit();
  virtual void onInitPostProcess();
  virtual void connectionCallback(const ros::SingleSubscriberPublisher& pub);
  virtual void warnNeverSubscribedCallback(const ros::WallTimerEvent& event);
  virtual void subscribe() = 0;
  virtual void unsubscribe() = 0;

  template <class T>
  ros::Publisher advertise(ros::NodeHandle& nh, std::string topic, int queue_size, bool latch = false);

  boost::mutex connection_mutex_;
  boost::shared_ptr<ros::NodeHandle> nh_;
  boost::shared_ptr<ros::NodeHandle> pnh_;
  std::vector<ros::Publisher> publishers_;
  ros::WallTimer timer_ever_subscribed_;
  bool ever_subscribed_;
  bool lazy_;
  ConnectionStatus connection_status_;
  bool verbose_connection_;
};

}  // namespace nodelet_topic_tools

#endif  // RSIA_MODEL_NODELET_TOPIC_TOOLS_NODELET_LAZY_H
