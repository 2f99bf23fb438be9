# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A Qt widget node: its QTimer's slot publishes, at the timer's rate.

The model mode has QObject and QTimer but no QWidget, QString::split or
QStringList: the widget class has no base the parse knows, and its
``connect(timer_, &QTimer::timeout, this, &TeleopGui::tick)`` is lost by
the AST. The timer, read from the tokens, is a loss a repair wins: the
publisher is driven by a 20 Hz timer, not by the node's subscription.
Expectations written by hand from the code below.
"""

from conftest import analyze_source

TELEOP_GUI = r"""
#include <QApplication>
#include <QTimer>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <ros/ros.h>
#include <std_msgs/String.h>

class TeleopGui : public QWidget
{
  Q_OBJECT
public:
  TeleopGui(ros::NodeHandle& nh, const QString& topics) : QWidget(nullptr)
  {
    QStringList parts = topics.split(',', Qt::SkipEmptyParts);
    cmd_ = nh.advertise<std_msgs::String>("cmd", 1);
    sub_ = nh.subscribe("joy", 1, &TeleopGui::joy, this);
    timer_ = new QTimer(this);
    connect(timer_, &QTimer::timeout, this, &TeleopGui::tick);
    timer_->start(50);
  }

private Q_SLOTS:
  void tick()
  {
    std_msgs::String msg;
    msg.data = last_;
    cmd_.publish(msg);
  }

private:
  void joy(const std_msgs::String::ConstPtr& m) { last_ = m->data; }
  std::string last_;
  ros::Subscriber sub_;
  QTimer* timer_;
  ros::Publisher cmd_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "teleop_gui");
  QApplication app(argc, argv);
  ros::NodeHandle nh;
  TeleopGui gui(nh, QString("a,b"));
  return app.exec();
}
"""


def test_a_widgets_timer_slot_publishes_at_the_timers_rate(tmp_path):
    summary = analyze_source(tmp_path, 'teleop_gui', TELEOP_GUI,
                             repair='when-it-pays')
    [node] = summary.nodes
    [publisher] = node.publishers
    assert (publisher.topic, publisher.label, publisher.rate_hz) == (
        'cmd', 'independent', 20.0)
    [timer] = node.timers
    assert (timer.callback, timer.rate_hz) == ('TeleopGui::tick', 20.0)
    assert [s.topic for s in node.subscribers] == ['joy']
