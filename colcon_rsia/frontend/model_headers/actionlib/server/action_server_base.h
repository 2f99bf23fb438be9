// colcon-rsia model of <actionlib/server/action_server_base.h>.
#ifndef RSIA_MODEL_ACTIONLIB_SERVER_ACTION_SERVER_BASE_H
#define RSIA_MODEL_ACTIONLIB_SERVER_ACTION_SERVER_BASE_H

#include <boost/function.hpp>
#include <actionlib/action_definition.h>
#include <actionlib/server/server_goal_handle.h>
#include <ros/ros.h>

namespace actionlib
{

template <class ActionSpec>
class ActionServerBase
{
public:
  typedef ServerGoalHandle<ActionSpec> GoalHandle;
  ACTION_DEFINITION(ActionSpec)

  ActionServerBase(boost::function<void(GoalHandle)> goal_cb, boost::function<void(GoalHandle)> cancel_cb,
                   bool auto_start = false);
  virtual ~ActionServerBase();

  void registerGoalCallback(boost::function<void(GoalHandle)> cb);
  void registerCancelCallback(boost::function<void(GoalHandle)> cb);
  void start();
};

}  // namespace actionlib

#endif  // RSIA_MODEL_ACTIONLIB_SERVER_ACTION_SERVER_BASE_H
