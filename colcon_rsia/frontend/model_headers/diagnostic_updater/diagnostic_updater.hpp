// colcon-rsia model of <diagnostic_updater/diagnostic_updater.hpp> (ROS 2,
// Humble/Jazzy/Rolling). Every Updater object publishes /diagnostics. Unlike
// ROS 1, the constructor also creates a timer on the node that calls
// update() every `period` seconds (argument 2, default 1.0; the node
// parameter `diagnostic_updater.period` overrides it when set), so the
// Updater publishes by itself; force_update and broadcast publish at once.
// add() publishes one "Node starting up" status per task when it is called.
#ifndef RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTIC_UPDATER_HPP
#define RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTIC_UPDATER_HPP

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <rclcpp/rclcpp.hpp>
#include <diagnostic_msgs/msg/diagnostic_array.hpp>
#include <diagnostic_msgs/msg/diagnostic_status.hpp>
#include <diagnostic_updater/diagnostic_status_wrapper.hpp>

// node interfaces the Updater's second constructor takes (declared here
// in case the rclcpp model does not declare them)
namespace rclcpp
{
namespace node_interfaces
{
class NodeLoggingInterface;
class NodeParametersInterface;
}  // namespace node_interfaces
}  // namespace rclcpp

namespace diagnostic_updater
{

using TaskFunction = std::function<void (DiagnosticStatusWrapper &)>;
using UnwrappedTaskFunction = std::function<void (diagnostic_msgs::msg::DiagnosticStatus &)>;

class DiagnosticTask
{
public:
  explicit DiagnosticTask(const std::string name);
  const std::string & getName();
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper & stat) = 0;
  virtual ~DiagnosticTask();
};

template<class T>
class GenericFunctionDiagnosticTask : public DiagnosticTask
{
public:
  GenericFunctionDiagnosticTask(const std::string & name, std::function<void(T &)> fn);
  virtual void run(DiagnosticStatusWrapper & stat);
};

using UnwrappedFunctionDiagnosticTask =
  GenericFunctionDiagnosticTask<diagnostic_msgs::msg::DiagnosticStatus>;
using FunctionDiagnosticTask = GenericFunctionDiagnosticTask<DiagnosticStatusWrapper>;

class CompositeDiagnosticTask : public DiagnosticTask
{
public:
  explicit CompositeDiagnosticTask(const std::string name);
  virtual void run(DiagnosticStatusWrapper & stat);
  void addTask(DiagnosticTask * t);
};

class DiagnosticTaskVector
{
public:
  void add(const std::string & name, TaskFunction f);
  void add(DiagnosticTask & task);
  template<class T>
  void add(
    const std::string name, T * c,
    void (T::* f)(diagnostic_updater::DiagnosticStatusWrapper &));
  bool removeByName(const std::string name);
};

class Updater : public DiagnosticTaskVector
{
public:
  bool verbose_;

  template<class NodeT>
  explicit Updater(NodeT node, double period = 1.0);
  Updater(
    std::shared_ptr<rclcpp::node_interfaces::NodeBaseInterface> base_interface,
    std::shared_ptr<rclcpp::node_interfaces::NodeClockInterface> clock_interface,
    std::shared_ptr<rclcpp::node_interfaces::NodeLoggingInterface> logging_interface,
    std::shared_ptr<rclcpp::node_interfaces::NodeParametersInterface> parameters_interface,
    std::shared_ptr<rclcpp::node_interfaces::NodeTimersInterface> timers_interface,
    std::shared_ptr<rclcpp::node_interfaces::NodeTopicsInterface> topics_interface,
    double period = 1.0);

  void update();
  void force_update();
  rclcpp::Duration getPeriod() const;
  void setPeriod(rclcpp::Duration period);
  void setPeriod(double period);
  void broadcast(unsigned char lvl, const std::string msg);
  void setHardwareIDf(const char * format, ...);
  void setHardwareID(const std::string & hwid);
};

}  // namespace diagnostic_updater

#endif  // RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTIC_UPDATER_HPP
