# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A package function that makes an endpoint of its parameter: one per call.

Expectations written by hand from the code below: the node runs once,
unnamespaced, under its default name.
"""

from conftest import analyze_source

SUBSCRIBED_PER_CALL = r"""
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <nav_msgs/Odometry.h>
#include <string>
#include <vector>

constexpr char kImuTopic[] = "imu";

class Node;

template <typename MessageType>
ros::Subscriber SubscribeWithHandler(ros::NodeHandle* nh,
                                     const std::string& topic) {
  return nh->subscribe<MessageType>(
      topic, 10, [](const typename MessageType::ConstPtr&) {});
}

std::vector<std::string> TopicNames(int count) {
  std::vector<std::string> names;
  for (int i = 0; i < count; ++i) names.push_back("scan_" + std::to_string(i));
  return names;
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "collector");
  ros::NodeHandle nh;
  std::vector<ros::Subscriber> subscribers;
  subscribers.push_back(SubscribeWithHandler<sensor_msgs::Imu>(&nh, kImuTopic));
  subscribers.push_back(
      SubscribeWithHandler<nav_msgs::Odometry>(&nh, "odom"));
  for (const std::string& topic : TopicNames(argc)) {
    subscribers.push_back(SubscribeWithHandler<sensor_msgs::Imu>(&nh, topic));
  }
  ros::spin();
}
"""


def test_each_call_of_a_subscribing_function_is_a_subscription(tmp_path):
    summary = analyze_source(tmp_path, 'collector', SUBSCRIBED_PER_CALL)
    [node] = summary.nodes
    # three calls, three subscriptions, where the function subscribes:
    # the constant's value, the literal, and the loop's variable, which
    # the code does not say (as written, not a name)
    assert sorted((s.topic, s.topic_is_literal, s.location)
                  for s in node.subscribers) == [
        ('imu', True, 'src/collector.cpp:15'),
        ('odom', True, 'src/collector.cpp:15'),
        ('topic', False, 'src/collector.cpp:15'),
    ]


PUBLISHED_ONCE_PER_HELPER = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

ros::Publisher Announce(ros::NodeHandle& nh, const std::string& topic,
                        int queue) {
  return nh.advertise<std_msgs::String>(topic + "/status", queue);
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "announcer");
  ros::NodeHandle nh;
  std::string arm = "arm";
  ros::Publisher left = Announce(nh, "left_" + arm, 1);
  ros::Publisher right = Announce(nh, "right", 1);
  ros::Rate rate(5);
  while (ros::ok()) {
    left.publish(std_msgs::String());
    right.publish(std_msgs::String());
    rate.sleep();
  }
}
"""


def test_what_the_function_adds_is_added_to_what_each_call_passes(tmp_path):
    summary = analyze_source(tmp_path, 'announcer', PUBLISHED_ONCE_PER_HELPER)
    [node] = summary.nodes
    # each call's name and the function's "/status": "left_" joined to
    # arm, set once to "arm", and "right"
    assert sorted((p.topic, p.topic_is_literal, p.location)
                  for p in node.publishers) == [
        ('left_arm/status', True, 'src/announcer.cpp:8'),
        ('right/status', True, 'src/announcer.cpp:8'),
    ]


NAMED_BY_ONE_CALLER_ONLY = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

ros::Publisher Advertise(ros::NodeHandle& nh, const std::string& topic) {
  return nh.advertise<std_msgs::String>(topic, 1);
}

void onName(const std_msgs::String::ConstPtr& name) {
  static ros::NodeHandle nh;
  static ros::Publisher echo = Advertise(nh, name->data);
}

int main(int argc, char** argv) {
  ros::init(argc, argv, "echo");
  ros::NodeHandle nh;
  ros::Publisher fixed = Advertise(nh, "fixed");
  ros::Subscriber sub = nh.subscribe("names", 1, onName);
  ros::spin();
}
"""


def test_a_name_one_call_passes_is_not_given_to_another(tmp_path):
    summary = analyze_source(tmp_path, 'echo', NAMED_BY_ONE_CALLER_ONLY)
    [node] = summary.nodes
    # "fixed" is one call's; the other passes a message's data, which the
    # code does not tell
    assert sorted((p.topic, p.topic_is_literal) for p in node.publishers) \
        == [('fixed', True), ('topic', False)]


LIBRARY_ADVERTISER = r"""#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

ros::Publisher Advertise(ros::NodeHandle& nh, const std::string& topic) {
  return nh.advertise<std_msgs::String>(topic, 1);
}
"""

LIBRARY_USER = r"""#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

ros::Publisher Advertise(ros::NodeHandle& nh, const std::string& topic);

int main(int argc, char** argv) {
  ros::init(argc, argv, "talker");
  ros::NodeHandle nh;
  ros::Publisher left = Advertise(nh, "left");
  ros::Publisher right = Advertise(nh, "right");
  ros::Rate rate(5);
  while (ros::ok()) {
    left.publish(std_msgs::String());
    right.publish(std_msgs::String());
    rate.sleep();
  }
}
"""

LIBRARY_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(talking)
find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
catkin_package()
add_library(advertiser src/advertiser.cpp)
add_executable(talker src/talker.cpp)
target_link_libraries(talker advertiser ${catkin_LIBRARIES})
"""


def test_a_library_function_of_the_package_is_placed_at_its_call(tmp_path):
    package = tmp_path / 'talking'
    (package / 'src').mkdir(parents=True)
    (package / 'src' / 'advertiser.cpp').write_text(LIBRARY_ADVERTISER)
    summary = analyze_source(tmp_path, 'talking', LIBRARY_USER,
                             file='src/talker.cpp', cmake=LIBRARY_CMAKE)
    [node] = summary.nodes
    assert node.id == 'talking/talker'
    # the executable links the library as it would another package's: each
    # publisher is where the node calls Advertise (talker.cpp:10 and 11),
    # made by the library at advertiser.cpp:6; the Rate loop paces both
    assert sorted((p.topic, p.location, p.made_in, p.label)
                  for p in node.publishers) == [
        ('left', 'src/talker.cpp:10', 'src/advertiser.cpp:6', 'independent'),
        ('right', 'src/talker.cpp:11', 'src/advertiser.cpp:6',
         'independent'),
    ]
    # the library's advertise is the node's: covered, not an orphan
    [site] = [c for c in summary.coverage.call_sites
              if c.file == 'src/advertiser.cpp']
    assert (site.line, site.recorded) == (6, 'node')
