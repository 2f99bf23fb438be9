// colcon-rsia model of <actionlib/client/simple_action_client.h>.
#ifndef RSIA_MODEL_ACTIONLIB_CLIENT_SIMPLE_ACTION_CLIENT_H
#define RSIA_MODEL_ACTIONLIB_CLIENT_SIMPLE_ACTION_CLIENT_H

#include <string>

#include <boost/function.hpp>
#include <boost/shared_ptr.hpp>
#include <boost/thread.hpp>
#include <actionlib/action_definition.h>
#include <actionlib/client/action_client.h>
#include <actionlib/client/simple_client_goal_state.h>
#include <actionlib/client/terminal_state.h>
#include <ros/ros.h>

namespace actionlib
{

template <class ActionSpec>
class SimpleActionClient
{
private:
  ACTION_DEFINITION(ActionSpec)
  typedef ClientGoalHandle<ActionSpec> GoalHandleT;
  typedef SimpleActionClient<ActionSpec> SimpleActionClientT;

public:
  typedef boost::function<void(const SimpleClientGoalState& state, const ResultConstPtr& result)>
      SimpleDoneCallback;
  typedef boost::function<void()> SimpleActiveCallback;
  typedef boost::function<void(const FeedbackConstPtr& feedback)> SimpleFeedbackCallback;

  SimpleActionClient(const std::string& name, bool spin_thread = true);
  SimpleActionClient(ros::NodeHandle& n, const std::string& name, bool spin_thread = true);
  ~SimpleActionClient();

  bool waitForServer(const ros::Duration& timeout = ros::Duration(0, 0)) const;
  bool isServerConnected() const;
  void sendGoal(const Goal& goal, SimpleDoneCallback done_cb = SimpleDoneCallback(),
                SimpleActiveCallback active_cb = SimpleActiveCallback(),
                SimpleFeedbackCallback feedback_cb = SimpleFeedbackCallback());
  SimpleClientGoalState sendGoalAndWait(const Goal& goal, const ros::Duration& execute_timeout = ros::Duration(0, 0),
                                        const ros::Duration& preempt_timeout = ros::Duration(0, 0));
  bool waitForResult(const ros::Duration& timeout = ros::Duration(0, 0));
  ResultConstPtr getResult() const;
  SimpleClientGoalState getState() const;
  void cancelAllGoals();
  void cancelGoalsAtAndBeforeTime(const ros::Time& time);
  void cancelGoal();
  void stopTrackingGoal();
};

}  // namespace actionlib

#endif  // RSIA_MODEL_ACTIONLIB_CLIENT_SIMPLE_ACTION_CLIENT_H
