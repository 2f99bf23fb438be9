// colcon-rsia model of <diagnostic_updater/DiagnosticStatusWrapper.h>.
#ifndef RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTICSTATUSWRAPPER_H
#define RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTICSTATUSWRAPPER_H

#include <sstream>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <diagnostic_msgs/KeyValue.h>
#include <ros/ros.h>

namespace diagnostic_updater
{

class DiagnosticStatusWrapper : public diagnostic_msgs::DiagnosticStatus
{
public:
  void summary(unsigned char lvl, const std::string s);
  void mergeSummary(unsigned char lvl, const std::string s);
  void mergeSummary(const diagnostic_msgs::DiagnosticStatus& src);
  void mergeSummaryf(unsigned char lvl, const char* format, ...);
  void summaryf(unsigned char lvl, const char* format, ...);
  void clearSummary();
  void summary(const diagnostic_msgs::DiagnosticStatus& src);
  template <class T>
  void add(const std::string& key, const T& val);
  void addf(const std::string& key, const char* format, ...);
  void clear();
};

}  // namespace diagnostic_updater

#endif  // RSIA_MODEL_DIAGNOSTIC_UPDATER_DIAGNOSTICSTATUSWRAPPER_H
