// colcon-rsia model of <actionlib/client/action_client.h> (with the
// ClientGoalHandle of client_helpers.h).
#ifndef RSIA_MODEL_ACTIONLIB_CLIENT_ACTION_CLIENT_H
#define RSIA_MODEL_ACTIONLIB_CLIENT_ACTION_CLIENT_H

#include <string>

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <actionlib/action_definition.h>
#include <actionlib/client/terminal_state.h>
#include <actionlib_msgs/GoalID.h>
#include <actionlib_msgs/GoalStatusArray.h>
#include <ros/ros.h>

namespace actionlib
{

template <class ActionSpec>
class ClientGoalHandle
{
public:
  ACTION_DEFINITION(ActionSpec)

  ClientGoalHandle();
  ~ClientGoalHandle();

  void reset();
  bool isExpired() const;
  CommState getCommState() const;
  TerminalState getTerminalState() const;
  ResultConstPtr getResult() const;
  void resend();
  void cancel();
  bool operator==(const ClientGoalHandle<ActionSpec>& rhs) const;
  bool operator!=(const ClientGoalHandle<ActionSpec>& rhs) const;
};

template <class ActionSpec>
class ActionClient
{
public:
  typedef ClientGoalHandle<ActionSpec> GoalHandle;
  ACTION_DEFINITION(ActionSpec)
  typedef boost::function<void(GoalHandle)> TransitionCallback;
  typedef boost::function<void(GoalHandle, const FeedbackConstPtr&)> FeedbackCallback;
  typedef boost::function<void(const ActionGoalConstPtr)> SendGoalFunc;

  ActionClient(const std::string& name, ros::CallbackQueueInterface* queue = NULL);
  ActionClient(const ros::NodeHandle& n, const std::string& name, ros::CallbackQueueInterface* queue = NULL);
  ~ActionClient();

  GoalHandle sendGoal(const Goal& goal, TransitionCallback transition_cb = TransitionCallback(),
                      FeedbackCallback feedback_cb = FeedbackCallback());
  void cancelAllGoals();
  void cancelGoalsAtAndBeforeTime(const ros::Time& time);
  bool waitForActionServerToStart(const ros::Duration& timeout = ros::Duration(0, 0));
  bool isServerConnected() const;
};

}  // namespace actionlib

#endif  // RSIA_MODEL_ACTIONLIB_CLIENT_ACTION_CLIENT_H
