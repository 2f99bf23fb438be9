// colcon-rsia model of <actionlib/action_definition.h>: the typedefs an action
// type provides (goal, result, feedback and their action wrappers, pointers).
#ifndef RSIA_MODEL_ACTIONLIB_ACTION_DEFINITION_H
#define RSIA_MODEL_ACTIONLIB_ACTION_DEFINITION_H

#include <boost/shared_ptr.hpp>

#define ACTION_DEFINITION(ActionSpec)                                           \
  typedef typename ActionSpec::_action_goal_type ActionGoal;                    \
  typedef typename ActionGoal::_goal_type Goal;                                 \
  typedef typename ActionSpec::_action_result_type ActionResult;                \
  typedef typename ActionResult::_result_type Result;                           \
  typedef typename ActionSpec::_action_feedback_type ActionFeedback;            \
  typedef typename ActionFeedback::_feedback_type Feedback;                     \
  typedef boost::shared_ptr<const ActionGoal> ActionGoalConstPtr;               \
  typedef boost::shared_ptr<ActionGoal> ActionGoalPtr;                          \
  typedef boost::shared_ptr<const Goal> GoalConstPtr;                           \
  typedef boost::shared_ptr<const ActionResult> ActionResultConstPtr;           \
  typedef boost::shared_ptr<const Result> ResultConstPtr;                       \
  typedef boost::shared_ptr<const ActionFeedback> ActionFeedbackConstPtr;       \
  typedef boost::shared_ptr<const Feedback> FeedbackConstPtr;

#endif  // RSIA_MODEL_ACTIONLIB_ACTION_DEFINITION_H
