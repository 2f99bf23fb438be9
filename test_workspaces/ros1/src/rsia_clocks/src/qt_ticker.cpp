// A ROS node driven by Qt's event loop, as GUI-less simulators are: the
// periodic work comes from Qt timers, never from a ros::Rate or ros::Timer.
#include <chrono>

#include <QCoreApplication>
#include <QObject>
#include <QTimer>
#include <QTimerEvent>

#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>
#include <std_msgs/UInt32.h>

class Ticker : public QObject
{
  Q_OBJECT

public:
  explicit Ticker(ros::NodeHandle & nh)
  {
    frame_pub_ = nh.advertise<std_msgs::UInt32>("frames", 10);
    pulse_pub_ = nh.advertise<std_msgs::Empty>("pulse", 1);
    heartbeat_pub_ = nh.advertise<std_msgs::Empty>("ticker_heartbeat", 1);
    ready_pub_ = nh.advertise<std_msgs::Empty>("ticker_ready", 1, true);
    echo_pub_ = nh.advertise<std_msgs::String>("ticker_echo", 10);
    command_sub_ = nh.subscribe("ticker_command", 10, &Ticker::onCommand, this);

    // every 16 ms, the old-style connection (turtlesim's)
    update_timer_ = new QTimer(this);
    update_timer_->setInterval(16);
    connect(update_timer_, SIGNAL(timeout()), this, SLOT(onUpdate()));
    update_timer_->start();

    // every 100 ms, a lambda through the functor connection
    pulse_timer_ = new QTimer(this);
    connect(pulse_timer_, &QTimer::timeout, [this]() {
        pulse_pub_.publish(std_msgs::Empty());
      });
    pulse_timer_->start(std::chrono::milliseconds(100));

    // fires once: not a clock
    ready_timer_ = new QTimer(this);
    ready_timer_->setSingleShot(true);
    connect(ready_timer_, &QTimer::timeout, this, &Ticker::onReady);
    ready_timer_->start(500);

    // QObject's own timer: timerEvent() every 250 ms
    startTimer(250);
  }

private slots:
  void onUpdate()
  {
    ros::spinOnce();
    std_msgs::UInt32 frame;
    frame.data = ++frames_;
    frame_pub_.publish(frame);
  }

  void onReady()
  {
    ready_pub_.publish(std_msgs::Empty());
  }

protected:
  void timerEvent(QTimerEvent *) override
  {
    heartbeat_pub_.publish(std_msgs::Empty());
  }

private:
  void onCommand(const std_msgs::String::ConstPtr & msg)
  {
    echo_pub_.publish(*msg);
  }

  ros::Publisher frame_pub_;
  ros::Publisher pulse_pub_;
  ros::Publisher heartbeat_pub_;
  ros::Publisher ready_pub_;
  ros::Publisher echo_pub_;
  ros::Subscriber command_sub_;
  QTimer * update_timer_;
  QTimer * pulse_timer_;
  QTimer * ready_timer_;
  unsigned frames_ = 0;
};

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "qt_ticker");
  QCoreApplication app(argc, argv);
  ros::NodeHandle nh;
  Ticker ticker(nh);
  return app.exec();
}

#include "qt_ticker.moc"
