// A helper compiled into rsia_common's library (src/status_board.cpp): the
// other packages see only this declaration, so the analysis of this package
// stores the helper's summary and the packages built after it read it at
// their call sites.
#ifndef RSIA_COMMON_STATUS_BOARD_H
#define RSIA_COMMON_STATUS_BOARD_H

#include <string>

#include <ros/ros.h>

namespace rsia_common
{

// the constructor advertises the topic it is given; post() publishes on it
class StatusBoard
{
public:
  StatusBoard(ros::NodeHandle& nh, const std::string& topic);
  void post(const std::string& text);

private:
  ros::Publisher publisher_;
};

}  // namespace rsia_common

#endif  // RSIA_COMMON_STATUS_BOARD_H
