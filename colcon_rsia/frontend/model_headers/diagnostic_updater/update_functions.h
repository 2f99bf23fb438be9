// colcon-rsia model of <diagnostic_updater/update_functions.h>.
#ifndef RSIA_MODEL_DIAGNOSTIC_UPDATER_UPDATE_FUNCTIONS_H
#define RSIA_MODEL_DIAGNOSTIC_UPDATER_UPDATE_FUNCTIONS_H

#include <string>

#include <diagnostic_updater/diagnostic_updater.h>

namespace diagnostic_updater
{

struct FrequencyStatusParam
{
  FrequencyStatusParam(double* min_freq, double* max_freq, double tolerance = 0.1, int window_size = 5);
  double* min_freq_;
  double* max_freq_;
  double tolerance_;
  int window_size_;
};

class FrequencyStatus : public DiagnosticTask
{
public:
  FrequencyStatus(const FrequencyStatusParam& params, std::string name);
  FrequencyStatus(const FrequencyStatusParam& params);
  void clear();
  void tick();
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper& stat);
};

struct TimeStampStatusParam
{
  TimeStampStatusParam(const double min_acceptable = -1, const double max_acceptable = 5);
  double max_acceptable_;
  double min_acceptable_;
};

class TimeStampStatus : public DiagnosticTask
{
public:
  TimeStampStatus(const TimeStampStatusParam& params, std::string name);
  TimeStampStatus(const TimeStampStatusParam& params);
  TimeStampStatus();
  void tick(double stamp);
  void tick(const ros::Time t);
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper& stat);
};

class SlowTimeStampStatus : public TimeStampStatus
{
public:
  SlowTimeStampStatus(const TimeStampStatusParam& params, const std::string& name);
  SlowTimeStampStatus(const TimeStampStatusParam& params);
  SlowTimeStampStatus();
};

class Heartbeat : public DiagnosticTask
{
public:
  Heartbeat();
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper& stat);
};

}  // namespace diagnostic_updater

#endif  // RSIA_MODEL_DIAGNOSTIC_UPDATER_UPDATE_FUNCTIONS_H
