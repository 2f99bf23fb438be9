// A node whose clock is a boost::asio io_context: handlers that arm their
// timer again run periodically; a handler that does not runs once.
#include <chrono>

#include <boost/asio/deadline_timer.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/placeholders.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/bind/bind.hpp>
#include <boost/date_time/posix_time/posix_time_types.hpp>
#include <boost/system/error_code.hpp>

#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/UInt32.h>

class Beacon
{
public:
  Beacon(boost::asio::io_context & io, ros::NodeHandle & nh)
  : beacon_timer_(io, std::chrono::milliseconds(50)),
    status_timer_(io),
    start_timer_(io)
  {
    beacon_pub_ = nh.advertise<std_msgs::UInt32>("beacon", 10);
    status_pub_ = nh.advertise<std_msgs::UInt32>("beacon_status", 1);
    started_pub_ = nh.advertise<std_msgs::Empty>("beacon_started", 1, true);
    reset_pub_ = nh.advertise<std_msgs::Empty>("beacon_reset_done", 1);
    reset_sub_ = nh.subscribe("beacon_reset", 1, &Beacon::onReset, this);

    // 20 Hz: the handler is a lambda calling tick(), which arms it again
    beacon_timer_.async_wait(
      [this](const boost::system::error_code & error) {tick(error);});

    // every 2 s: a bound method that arms its own timer again
    status_timer_.expires_from_now(boost::posix_time::seconds(2));
    status_timer_.async_wait(
      boost::bind(&Beacon::report, this, boost::asio::placeholders::error));

    // once, one second after the start
    start_timer_.expires_after(std::chrono::seconds(1));
    start_timer_.async_wait(
      boost::bind(&Beacon::started, this, boost::asio::placeholders::error));
  }

private:
  void tick(const boost::system::error_code & error)
  {
    if (error) {
      return;
    }
    std_msgs::UInt32 count;
    count.data = ++beacons_;
    beacon_pub_.publish(count);
    beacon_timer_.expires_at(
      beacon_timer_.expiry() + std::chrono::milliseconds(50));
    beacon_timer_.async_wait(
      [this](const boost::system::error_code & again) {tick(again);});
  }

  void report(const boost::system::error_code &)
  {
    std_msgs::UInt32 status;
    status.data = beacons_;
    status_pub_.publish(status);
    status_timer_.expires_at(
      status_timer_.expires_at() + boost::posix_time::seconds(2));
    status_timer_.async_wait(
      boost::bind(&Beacon::report, this, boost::asio::placeholders::error));
  }

  void started(const boost::system::error_code &)
  {
    started_pub_.publish(std_msgs::Empty());
  }

  void onReset(const std_msgs::Empty::ConstPtr &)
  {
    beacons_ = 0;
    reset_pub_.publish(std_msgs::Empty());
  }

  boost::asio::steady_timer beacon_timer_;
  boost::asio::deadline_timer status_timer_;
  boost::asio::steady_timer start_timer_;
  ros::Publisher beacon_pub_;
  ros::Publisher status_pub_;
  ros::Publisher started_pub_;
  ros::Publisher reset_pub_;
  ros::Subscriber reset_sub_;
  unsigned beacons_ = 0;
};

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "asio_beacon");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  spinner.start();
  boost::asio::io_context io;
  Beacon beacon(io, nh);
  io.run();
  return 0;
}
