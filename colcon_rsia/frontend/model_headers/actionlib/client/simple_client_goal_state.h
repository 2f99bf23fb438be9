// colcon-rsia model of <actionlib/client/simple_client_goal_state.h>.
#ifndef RSIA_MODEL_ACTIONLIB_CLIENT_SIMPLE_CLIENT_GOAL_STATE_H
#define RSIA_MODEL_ACTIONLIB_CLIENT_SIMPLE_CLIENT_GOAL_STATE_H

#include <string>

namespace actionlib
{

class SimpleClientGoalState
{
public:
  enum StateEnum
  {
    PENDING,
    ACTIVE,
    RECALLED,
    REJECTED,
    PREEMPTED,
    ABORTED,
    SUCCEEDED,
    LOST
  };

  StateEnum state_;
  std::string text_;

  SimpleClientGoalState(const StateEnum& state, const std::string& text = std::string(""));

  bool operator==(const SimpleClientGoalState& rhs) const;
  bool operator==(const SimpleClientGoalState::StateEnum& rhs) const;
  bool operator==(const int& rhs) const;
  bool operator!=(const SimpleClientGoalState::StateEnum& rhs) const;
  bool operator!=(const SimpleClientGoalState& rhs) const;
  bool isDone() const;
  std::string getText() const;
  std::string toString() const;
};

}  // namespace actionlib

#endif  // RSIA_MODEL_ACTIONLIB_CLIENT_SIMPLE_CLIENT_GOAL_STATE_H
