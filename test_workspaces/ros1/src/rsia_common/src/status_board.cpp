#include "rsia_common/status_board.h"

#include <std_msgs/String.h>

namespace rsia_common
{

StatusBoard::StatusBoard(ros::NodeHandle& nh, const std::string& topic)
{
  publisher_ = nh.advertise<std_msgs::String>(topic, 5);
}

void StatusBoard::post(const std::string& text)
{
  std_msgs::String message;
  message.data = text;
  publisher_.publish(message);
}

}  // namespace rsia_common
