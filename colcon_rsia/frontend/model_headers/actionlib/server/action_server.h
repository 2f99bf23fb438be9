// colcon-rsia model of <actionlib/server/action_server.h>: an action server
// whose goal and cancel callbacks are roots.
#ifndef RSIA_MODEL_ACTIONLIB_SERVER_ACTION_SERVER_H
#define RSIA_MODEL_ACTIONLIB_SERVER_ACTION_SERVER_H

#include <string>

#include <boost/function.hpp>
#include <actionlib/action_definition.h>
#include <actionlib/server/action_server_base.h>
#include <actionlib/server/server_goal_handle.h>
#include <actionlib_msgs/GoalID.h>
#include <actionlib_msgs/GoalStatusArray.h>
#include <ros/ros.h>

namespace actionlib
{

template <class ActionSpec>
class ActionServer : public ActionServerBase<ActionSpec>
{
public:
  typedef ServerGoalHandle<ActionSpec> GoalHandle;
  ACTION_DEFINITION(ActionSpec)

  ActionServer(ros::NodeHandle n, std::string name, boost::function<void(GoalHandle)> goal_cb,
               boost::function<void(GoalHandle)> cancel_cb, bool auto_start);
  ActionServer(ros::NodeHandle n, std::string name, boost::function<void(GoalHandle)> goal_cb,
               bool auto_start);
  ActionServer(ros::NodeHandle n, std::string name, boost::function<void(GoalHandle)> goal_cb,
               boost::function<void(GoalHandle)> cancel_cb = boost::function<void(GoalHandle)>());
  ActionServer(ros::NodeHandle n, std::string name, bool auto_start);
  ActionServer(ros::NodeHandle n, std::string name);
  virtual ~ActionServer();
};

}  // namespace actionlib

#endif  // RSIA_MODEL_ACTIONLIB_SERVER_ACTION_SERVER_H
