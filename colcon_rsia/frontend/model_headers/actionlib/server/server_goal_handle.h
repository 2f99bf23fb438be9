// colcon-rsia model of <actionlib/server/server_goal_handle.h>.
#ifndef RSIA_MODEL_ACTIONLIB_SERVER_SERVER_GOAL_HANDLE_H
#define RSIA_MODEL_ACTIONLIB_SERVER_SERVER_GOAL_HANDLE_H

#include <string>

#include <actionlib/action_definition.h>
#include <actionlib_msgs/GoalID.h>
#include <actionlib_msgs/GoalStatus.h>
#include <boost/shared_ptr.hpp>
#include <ros/ros.h>

namespace actionlib
{

template <class ActionSpec>
class ActionServerBase;

template <class ActionSpec>
class ServerGoalHandle
{
public:
  ACTION_DEFINITION(ActionSpec)

  ServerGoalHandle();
  ServerGoalHandle(const ServerGoalHandle& gh);

  void setAccepted(const std::string& text = std::string(""));
  void setCanceled(const Result& result = Result(), const std::string& text = std::string(""));
  void setRejected(const Result& result = Result(), const std::string& text = std::string(""));
  void setAborted(const Result& result = Result(), const std::string& text = std::string(""));
  void setSucceeded(const Result& result = Result(), const std::string& text = std::string(""));
  void publishFeedback(const Feedback& feedback);
  bool isValid() const;
  boost::shared_ptr<const Goal> getGoal() const;
  actionlib_msgs::GoalID getGoalID() const;
  actionlib_msgs::GoalStatus getGoalStatus() const;
  ServerGoalHandle& operator=(const ServerGoalHandle& gh);
  bool operator==(const ServerGoalHandle& other) const;
  bool operator!=(const ServerGoalHandle& other) const;
};

}  // namespace actionlib

#endif  // RSIA_MODEL_ACTIONLIB_SERVER_SERVER_GOAL_HANDLE_H
