// colcon-rsia model of <diagnostic_updater/diagnostic_status_wrapper.hpp>
// (ROS 2; older ROS 2 releases name it DiagnosticStatusWrapper.hpp).
#ifndef RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTIC_STATUS_WRAPPER_HPP
#define RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTIC_STATUS_WRAPPER_HPP

#include <string>

#include <rclcpp/rclcpp.hpp>
#include <diagnostic_msgs/msg/diagnostic_status.hpp>
#include <diagnostic_msgs/msg/key_value.hpp>

namespace diagnostic_updater
{

class DiagnosticStatusWrapper : public diagnostic_msgs::msg::DiagnosticStatus
{
public:
  void summary(unsigned char lvl, const std::string s);
  void mergeSummary(unsigned char lvl, const std::string s);
  void mergeSummary(const diagnostic_msgs::msg::DiagnosticStatus & src);
  void mergeSummaryf(unsigned char lvl, const char * format, ...);
  void summaryf(unsigned char lvl, const char * format, ...);
  void clearSummary();
  void summary(const diagnostic_msgs::msg::DiagnosticStatus & src);
  template<class T>
  void add(const std::string & key, const T & val);
  void addf(const std::string & key, const char * format, ...);
  void clear();
};

}  // namespace diagnostic_updater

#endif  // RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTIC_STATUS_WRAPPER_HPP
