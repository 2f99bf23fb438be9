# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A Qt widget node: its QTimer's slot publishes, at the timer's rate.

The model has QtCore (QObject, QTimer, QString) but no QtWidgets: the
stand-in of a Qt class header the model lacks (<QWidget>) includes QtCore
and declares its class, made from anything and a QObject. The publisher
is driven by a 20 Hz timer, not by the node's subscription. (Where the
parse loses ``connect(timer_, &QTimer::timeout, ...)`` the token reader
reads it: tests/frontend/test_token_facts.py.) Expectations written by
hand from the code below.
"""

from conftest import analyze_source
from model_sources import assert_analyzes_clean

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


# a panel of widgets the model lacks, its moc keywords from QtCore; the
# model's QString, whose header it lacks, is not declared again
PANEL = r"""
#include <QPushButton>
#include <QString>
#include <QVBoxLayout>
#include <QtWidgets/QWidget>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Panel : public QWidget
{
  Q_OBJECT

public:
  explicit Panel(QWidget * parent = nullptr) : QWidget(parent)
  {
    node_ = std::make_shared<rclcpp::Node>("panel");
    pub_ = node_->create_publisher<std_msgs::msg::String>("clicked", 1);
    layout_ = new QVBoxLayout();
    button_ = new QPushButton("Go", this);
  }

private Q_SLOTS:
  void onClick() { pub_->publish(std_msgs::msg::String()); }

private:
  QVBoxLayout * layout_;
  QPushButton * button_;
  QString label_;
  rclcpp::Node::SharedPtr node_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""


def test_qt_class_headers_the_model_lacks_declare_their_class(tmp_path):
    # before: Q_OBJECT was repaired (a second parse), and 'QWidget',
    # 'QVBoxLayout', 'QPushButton' were unknown type names
    assert_analyzes_clean(tmp_path, 'panel', PANEL)
