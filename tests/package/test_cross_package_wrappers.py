# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Helpers compiled into another package's library, read at their calls.

rsia_ros2_common's GraphListener and make_gauge have their bodies in its
src/graph_listener.cpp; rsia_ros2_wrapped sees only their declarations.
The expectations of the relay itself are in
test_workspaces/ros2/expected/rsia_ros2_wrapped.yaml; these tests check
how the summaries travel: in dependency order, with the cache, and only
from packages of the workspace.
"""

import json
import shutil

from colcon_rsia.package import analysis
from conftest import WORKSPACES

SRC = WORKSPACES / 'ros2' / 'src'


def _workspace(tmp_path):
    for package in ('rsia_ros2_common', 'rsia_ros2_wrapped'):
        shutil.copytree(SRC / package, tmp_path / 'src' / package)
    return tmp_path / 'src'


def _analyze(src, build, package, package_dirs):
    return analysis.analyze_package(
        name=package, path=str(src / package), build_base=str(build / package),
        jobs=1, header_mode='model',
        workspace_package_dirs=[str(src / d) for d in package_dirs])


def _relay_topics(summary):
    (node,) = summary.nodes
    return ({p.topic for p in node.publishers},
            {s.topic for s in node.subscribers})


def test_a_library_helper_changed_changes_its_callers_facts(tmp_path):
    src = _workspace(tmp_path)
    build = tmp_path / 'build'
    both = ('rsia_ros2_common', 'rsia_ros2_wrapped')
    _analyze(src, build, 'rsia_ros2_common', both)
    publishers, subscribers = _relay_topics(
        _analyze(src, build, 'rsia_ros2_wrapped', both))
    assert {'graph_announcements', 'relay_gauge'} <= publishers
    assert subscribers == {'cmd_vel_in', 'graph_updates'}

    # the helper's body changes; the relay's own files do not, and its
    # cached facts must not hide the change
    helper = src / 'rsia_ros2_common' / 'src' / 'graph_listener.cpp'
    helper.write_text(helper.read_text().replace(
        '"graph_updates"', '"graph_changes"'))
    _analyze(src, build, 'rsia_ros2_common', both)
    _, subscribers = _relay_topics(
        _analyze(src, build, 'rsia_ros2_wrapped', both))
    assert subscribers == {'cmd_vel_in', 'graph_changes'}


def test_summaries_stored_for_another_source_tree_are_not_read(tmp_path):
    src = _workspace(tmp_path)
    build = tmp_path / 'build'
    # the build base holds the output of a package of the same name from
    # another source tree (a workspace moved or switched): stale output
    old = tmp_path / 'old'
    shutil.copytree(src / 'rsia_ros2_common', old / 'rsia_ros2_common')
    _analyze(old, build, 'rsia_ros2_common', ('rsia_ros2_common',))
    assert (build / 'rsia_ros2_common' / 'rsia' / 'wrappers.json').is_file()
    publishers, subscribers = _relay_topics(_analyze(
        src, build, 'rsia_ros2_wrapped',
        ('rsia_ros2_common', 'rsia_ros2_wrapped')))
    # the header's wrappers are read from this tree; the library's
    # helpers are unknown until this tree's rsia_ros2_common is analysed
    assert 'relay_status' in publishers
    assert not {'graph_announcements', 'relay_gauge'} & publishers
    assert subscribers == {'cmd_vel_in'}


def test_a_wrappers_file_of_another_version_is_no_crash(tmp_path):
    src = _workspace(tmp_path)
    build = tmp_path / 'build'
    both = ('rsia_ros2_common', 'rsia_ros2_wrapped')
    _analyze(src, build, 'rsia_ros2_common', both)
    stored = build / 'rsia_ros2_common' / 'rsia' / 'wrappers.json'
    data = json.loads(stored.read_text())
    for wrapper in data['wrappers']:
        for endpoint in wrapper['endpoints']:
            endpoint['queue_param'] = 2   # a field this version lacks
    stored.write_text(json.dumps(data))
    summary = _analyze(src, build, 'rsia_ros2_wrapped', both)
    assert not [d for d in summary.diagnostics if 'internal error' in d]
    publishers, _ = _relay_topics(summary)
    assert 'relay_status' in publishers and 'relay_gauge' not in publishers


LIFECYCLE_BASE = r"""
#pragma once
#include <functional>
#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "rclcpp_lifecycle/lifecycle_node.hpp"

namespace acme_common
{
// the workspace's own LifecycleNode: its endpoints all have depth 10
class LifecycleNode : public rclcpp_lifecycle::LifecycleNode
{
public:
  explicit LifecycleNode(const std::string & name)
  : rclcpp_lifecycle::LifecycleNode(name) {}

  template<typename MessageT>
  typename rclcpp_lifecycle::LifecyclePublisher<MessageT>::SharedPtr
  create_publisher(const std::string & topic)
  {
    return rclcpp_lifecycle::LifecycleNode::create_publisher<MessageT>(
      topic, rclcpp::QoS(10));
  }

  template<typename MessageT, typename CallbackT>
  typename rclcpp::Subscription<MessageT>::SharedPtr
  create_subscription(const std::string & topic, CallbackT && callback)
  {
    return rclcpp_lifecycle::LifecycleNode::create_subscription<MessageT>(
      topic, rclcpp::QoS(10), std::forward<CallbackT>(callback));
  }
};
}  // namespace acme_common
"""

PLANNER = r"""
#include <memory>
#include "acme_common/lifecycle_node.hpp"
#include "geometry_msgs/msg/pose_stamped.hpp"
#include "nav_msgs/msg/path.hpp"

class Planner : public acme_common::LifecycleNode
{
public:
  Planner() : acme_common::LifecycleNode("planner")
  {
    plan_pub_ = create_publisher<nav_msgs::msg::Path>("plan");
    goal_sub_ = create_subscription<geometry_msgs::msg::PoseStamped>(
      "goal", [this](geometry_msgs::msg::PoseStamped::ConstSharedPtr) {
        plan_pub_->publish(nav_msgs::msg::Path());
      });
  }

private:
  rclcpp_lifecycle::LifecyclePublisher<nav_msgs::msg::Path>::SharedPtr plan_pub_;
  rclcpp::Subscription<geometry_msgs::msg::PoseStamped>::SharedPtr goal_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Planner>();
  rclcpp::spin(node->get_node_base_interface());
}
"""


def test_a_lifecycle_node_subclass_of_another_package_wraps_the_api(
        tmp_path):
    """create_publisher<M>(topic) of the workspace's LifecycleNode subclass.

    The node calls its base's overrides, defined in another package's
    header: each is read through, the topic and message type are the
    node's own, and the publisher, published only from the goal
    subscription's callback, is dependent.
    """
    src = tmp_path / 'src'
    files = {
        'acme_common/include/acme_common/lifecycle_node.hpp': LIFECYCLE_BASE,
        'acme_common/CMakeLists.txt': 'project(acme_common)\n',
        'acme_planner/src/planner.cpp': PLANNER,
        'acme_planner/CMakeLists.txt': (
            'cmake_minimum_required(VERSION 3.8)\nproject(acme_planner)\n'
            'add_executable(planner src/planner.cpp)\n'),
    }
    for relative, text in files.items():
        (src / relative).parent.mkdir(parents=True, exist_ok=True)
        (src / relative).write_text(text)
    both = ('acme_common', 'acme_planner')
    summary = _analyze(src, tmp_path / 'build', 'acme_planner', both)
    (node,) = summary.nodes
    assert [(p.topic, p.msg_type, p.api, p.label)
            for p in node.publishers] == [
        ('plan', 'nav_msgs::msg::Path',
         'acme_common::LifecycleNode::create_publisher', 'dependent')]
    assert [(s.topic, s.msg_type, s.api, s.callback)
            for s in node.subscribers] == [
        ('goal', 'geometry_msgs::msg::PoseStamped',
         'acme_common::LifecycleNode::create_subscription',
         'lambda@src/planner.cpp:14')]


CONSTANT_CALLER = """
#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "rsia_ros2_common/endpoints.hpp"
#include "std_msgs/msg/string.hpp"

namespace
{
constexpr char kStatusTopic[] = "named_by_constant";
}

class Caller : public rclcpp::Node
{
public:
  Caller()
  : Node("caller"),
    input_topic_(declare_parameter("input_topic", "named_by_default"))
  {
    status_pub_ = rsia_ros2_common::make_publisher<std_msgs::msg::String>(
      this, kStatusTopic);
    input_sub_ = rsia_ros2_common::make_subscription<std_msgs::msg::String>(
      this, input_topic_,
      [this](const std_msgs::msg::String::SharedPtr msg) {
        status_pub_->publish(*msg);
      });
  }

private:
  std::string input_topic_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr input_sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Caller>());
}
"""


def test_a_wrapper_topic_passed_as_a_constant_or_parameter_is_named(
        tmp_path):
    # the call passes no literal: the topic comes from where a direct
    # call's would, a constant and a parameter's default
    src = tmp_path / 'src'
    shutil.copytree(SRC / 'rsia_ros2_common', src / 'rsia_ros2_common')
    caller = src / 'rsia_caller'
    (caller / 'src').mkdir(parents=True)
    (caller / 'src' / 'caller.cpp').write_text(CONSTANT_CALLER)
    (caller / 'package.xml').write_text(
        (SRC / 'rsia_ros2_wrapped' / 'package.xml').read_text().replace(
            'rsia_ros2_wrapped', 'rsia_caller'))
    (caller / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(rsia_caller)\n'
        'find_package(ament_cmake REQUIRED)\n'
        'add_executable(caller src/caller.cpp)\nament_package()\n')
    summary = _analyze(src, tmp_path / 'build', 'rsia_caller',
                       ('rsia_ros2_common', 'rsia_caller'))
    (node,) = summary.nodes
    assert [(p.topic, p.topic_is_literal) for p in node.publishers] == [
        ('named_by_constant', True)]
    (subscriber,) = node.subscribers
    assert subscriber.topic_param is not None
    assert (subscriber.topic_param.name, subscriber.topic_param.default) == \
        ('input_topic', 'named_by_default')
