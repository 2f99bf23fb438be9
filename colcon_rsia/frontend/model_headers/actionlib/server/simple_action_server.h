// colcon-rsia model of <actionlib/server/simple_action_server.h>: an action
// server whose execute, goal and preempt callbacks are roots.
#ifndef RSIA_MODEL_ACTIONLIB_SERVER_SIMPLE_ACTION_SERVER_H
#define RSIA_MODEL_ACTIONLIB_SERVER_SIMPLE_ACTION_SERVER_H

#include <string>

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <boost/thread.hpp>
#include <actionlib/action_definition.h>
#include <actionlib/server/action_server.h>
#include <ros/ros.h>

namespace actionlib
{

template <class ActionSpec>
class SimpleActionServer
{
public:
  ACTION_DEFINITION(ActionSpec)

  typedef typename ActionServer<ActionSpec>::GoalHandle GoalHandle;
  typedef boost::function<void(const GoalConstPtr&)> ExecuteCallback;

  SimpleActionServer(std::string name, ExecuteCallback execute_callback, bool auto_start);
  SimpleActionServer(std::string name, bool auto_start);
  SimpleActionServer(std::string name, ExecuteCallback execute_callback = NULL);
  SimpleActionServer(ros::NodeHandle n, std::string name, ExecuteCallback execute_callback, bool auto_start);
  SimpleActionServer(ros::NodeHandle n, std::string name, bool auto_start);
  SimpleActionServer(ros::NodeHandle n, std::string name, ExecuteCallback execute_callback = NULL);
  ~SimpleActionServer();

  boost::shared_ptr<const Goal> acceptNewGoal();
  bool isNewGoalAvailable();
  bool isPreemptRequested();
  bool isActive();
  void setSucceeded(const Result& result = Result(), const std::string& text = std::string(""));
  void setAborted(const Result& result = Result(), const std::string& text = std::string(""));
  void publishFeedback(const FeedbackConstPtr& feedback);
  void publishFeedback(const Feedback& feedback);
  void setPreempted(const Result& result = Result(), const std::string& text = std::string(""));
  void registerGoalCallback(boost::function<void()> cb);
  void registerPreemptCallback(boost::function<void()> cb);
  void start();
  void shutdown();
};

}  // namespace actionlib

#endif  // RSIA_MODEL_ACTIONLIB_SERVER_SIMPLE_ACTION_SERVER_H
