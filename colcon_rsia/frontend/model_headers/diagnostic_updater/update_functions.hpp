// colcon-rsia model of <diagnostic_updater/update_functions.hpp> (ROS 2).
#ifndef RSIA_MODEL_DIAGNOSTIC_UPDATER_UPDATE_FUNCTIONS_HPP
#define RSIA_MODEL_DIAGNOSTIC_UPDATER_UPDATE_FUNCTIONS_HPP

#include <memory>
#include <string>

#include <rclcpp/rclcpp.hpp>
#include <diagnostic_updater/diagnostic_updater.hpp>

namespace diagnostic_updater
{

struct FrequencyStatusParam
{
  FrequencyStatusParam(
    double * min_freq, double * max_freq, double tolerance = 0.1,
    int window_size = 5);
  double * min_freq_;
  double * max_freq_;
  double tolerance_;
  int window_size_;
};

class FrequencyStatus : public DiagnosticTask
{
public:
  FrequencyStatus(
    const FrequencyStatusParam & params, std::string name,
    const rclcpp::Clock::SharedPtr & clock = std::make_shared<rclcpp::Clock>());
  explicit FrequencyStatus(
    const FrequencyStatusParam & params,
    const rclcpp::Clock::SharedPtr & clock = std::make_shared<rclcpp::Clock>());
  void clear();
  void tick();
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper & stat);
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
  TimeStampStatus(
    const TimeStampStatusParam & params, std::string name,
    const rclcpp::Clock::SharedPtr & clock = std::make_shared<rclcpp::Clock>());
  explicit TimeStampStatus(
    const TimeStampStatusParam & params,
    const rclcpp::Clock::SharedPtr & clock = std::make_shared<rclcpp::Clock>());
  explicit TimeStampStatus(
    const rclcpp::Clock::SharedPtr & clock = std::make_shared<rclcpp::Clock>());
  void tick(double stamp);
  void tick(const rclcpp::Time & t);
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper & stat);
};

class Heartbeat : public DiagnosticTask
{
public:
  Heartbeat();
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper & stat);
};

}  // namespace diagnostic_updater

#endif  // RSIA_MODEL_DIAGNOSTIC_UPDATER_UPDATE_FUNCTIONS_HPP
