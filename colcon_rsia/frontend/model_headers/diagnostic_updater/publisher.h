// colcon-rsia model of <diagnostic_updater/publisher.h>: topic diagnostics and
// DiagnosedPublisher (publishes through the ros::Publisher it wraps).
#ifndef RSIA_MODEL_DIAGNOSTIC_UPDATER_PUBLISHER_H
#define RSIA_MODEL_DIAGNOSTIC_UPDATER_PUBLISHER_H

#include <string>

#include <boost/shared_ptr.hpp>
#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/update_functions.h>
#include <ros/publisher.h>

namespace diagnostic_updater
{

class HeaderlessTopicDiagnostic : public CompositeDiagnosticTask
{
public:
  HeaderlessTopicDiagnostic(std::string name, diagnostic_updater::Updater& diag,
                            const diagnostic_updater::FrequencyStatusParam& freq);
  virtual ~HeaderlessTopicDiagnostic();
  virtual void tick();
  virtual void run(diagnostic_updater::DiagnosticStatusWrapper& stat);
  void clear_window();
};

class TopicDiagnostic : public HeaderlessTopicDiagnostic
{
public:
  TopicDiagnostic(std::string name, diagnostic_updater::Updater& diag,
                  const diagnostic_updater::FrequencyStatusParam& freq,
                  const diagnostic_updater::TimeStampStatusParam& stamp);
  virtual ~TopicDiagnostic();
  virtual void tick();
  virtual void tick(const ros::Time& stamp);
};

template <class T>
class DiagnosedPublisher : public TopicDiagnostic
{
public:
  DiagnosedPublisher(const ros::Publisher& pub, diagnostic_updater::Updater& diag,
                     const diagnostic_updater::FrequencyStatusParam& freq,
                     const diagnostic_updater::TimeStampStatusParam& stamp);
  virtual ~DiagnosedPublisher();

  virtual void publish(const boost::shared_ptr<T>& message);
  virtual void publish(const T& message);
  ros::Publisher getPublisher() const;
  void setPublisher(ros::Publisher pub);
};

}  // namespace diagnostic_updater

#endif  // RSIA_MODEL_DIAGNOSTIC_UPDATER_PUBLISHER_H
