// colcon-rsia model of <actionlib/client/terminal_state.h>.
#ifndef RSIA_MODEL_ACTIONLIB_CLIENT_TERMINAL_STATE_H
#define RSIA_MODEL_ACTIONLIB_CLIENT_TERMINAL_STATE_H

#include <string>

namespace actionlib
{

class TerminalState
{
public:
  enum StateEnum
  {
    RECALLED,
    REJECTED,
    PREEMPTED,
    ABORTED,
    SUCCEEDED,
    LOST
  };

  StateEnum state_;
  std::string text_;

  TerminalState(const StateEnum& state, const std::string& text = std::string(""));
  bool operator==(const TerminalState& rhs) const;
  bool operator==(const TerminalState::StateEnum& rhs) const;
  bool operator!=(const TerminalState::StateEnum& rhs) const;
  std::string getText() const;
  std::string toString() const;
};

class CommState
{
public:
  enum StateEnum
  {
    WAITING_FOR_GOAL_ACK = 0,
    PENDING = 1,
    ACTIVE = 2,
    WAITING_FOR_RESULT = 3,
    WAITING_FOR_CANCEL_ACK = 4,
    RECALLING = 5,
    PREEMPTING = 6,
    DONE = 7
  };

  StateEnum state_;

  CommState(const StateEnum& state);
  bool operator==(const CommState& rhs) const;
  bool operator==(const CommState::StateEnum& rhs) const;
  bool operator!=(const CommState::StateEnum& rhs) const;
  bool operator!=(const CommState& rhs) const;
  std::string toString() const;
};

}  // namespace actionlib

#endif  // RSIA_MODEL_ACTIONLIB_CLIENT_TERMINAL_STATE_H
