// colcon-rsia model of <diagnostic_updater/diagnostic_updater.h>: every Updater
// object publishes /diagnostics; update, force_update and broadcast are its
// publish sites (it has no timer of its own).
#ifndef RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTIC_UPDATER_H
#define RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTIC_UPDATER_H

#include <stdexcept>
#include <string>
#include <vector>

#include <boost/function.hpp>
#include <boost/thread.hpp>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <diagnostic_msgs/DiagnosticStatus.h>
#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <ros/node_handle.h>
#include <ros/this_node.h>

namespace diagnostic_updater
{

typedef boost::function<void(DiagnosticStatusWrapper&)> TaskFunction;
typedef boost::function<void(diagnostic_msgs::DiagnosticStatus&)> UnwrappedTaskFunction;

class DiagnosticTask
{
public:
  DiagnosticTask(const std::string name);
  const std::string& getName();
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper& stat) = 0;
  virtual ~DiagnosticTask();
};

template <class T>
class GenericFunctionDiagnosticTask : public DiagnosticTask
{
public:
  GenericFunctionDiagnosticTask(const std::string& name, boost::function<void(T&)> fn);
  virtual void run(DiagnosticStatusWrapper& stat);
};

typedef GenericFunctionDiagnosticTask<diagnostic_msgs::DiagnosticStatus> UnwrappedFunctionDiagnosticTask;
typedef GenericFunctionDiagnosticTask<DiagnosticStatusWrapper> FunctionDiagnosticTask;

class CompositeDiagnosticTask : public DiagnosticTask
{
public:
  CompositeDiagnosticTask(const std::string name);
  virtual void run(DiagnosticStatusWrapper& stat);
  void addTask(DiagnosticTask* t);
};

class DiagnosticTaskVector
{
public:
  void add(const std::string& name, TaskFunction f);
  void add(DiagnosticTask& task);
  template <class T>
  void add(const std::string name, T* c, void (T::*f)(diagnostic_updater::DiagnosticStatusWrapper&));
  bool removeByName(const std::string name);
};

class Updater : public DiagnosticTaskVector
{
public:
  bool verbose_;

  Updater(ros::NodeHandle h = ros::NodeHandle(), ros::NodeHandle ph = ros::NodeHandle("~"),
          std::string node_name = ros::this_node::getName());

  void update();
  void force_update();
  double getPeriod();
  void broadcast(int lvl, const std::string msg);
  void setHardwareIDf(const char* format, ...);
  void setHardwareID(const std::string& hwid);
};

}  // namespace diagnostic_updater

#endif  // RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTIC_UPDATER_H
