# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""C++ topic names built from values: concatenation, ros::names::append.

Expectations written by hand from the code below.
"""

from colcon_rsia.system.graph import build_graph
from colcon_rsia.system.graph import Instance
from conftest import analyze_source
import pytest

BUILT_NAMES = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

void onIn(const std_msgs::String::ConstPtr&) {}

void advertiseUnder(ros::NodeHandle& nh, const std::string& prefix,
                    ros::Publisher& out)
{
  std::string robot = "turtle1";
  // `prefix` is whatever the caller passes: not known
  out = nh.advertise<std_msgs::String>(robot + "/" + prefix, 1);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "built_names");
  ros::NodeHandle nh;
  std::string ns = "turtle1";
  std::string name = "color";
  ros::Publisher pose = nh.advertise<std_msgs::String>(ns + "/pose", 1);
  ros::Publisher color = nh.advertise<std_msgs::String>(std::string("~") + name, 1);
  ros::Publisher cmd = nh.advertise<std_msgs::String>(
      ros::names::append(ns, "cmd_vel"), 1);
  ros::Subscriber in = nh.subscribe("/" + ns + "/in", 1, onIn);
  ros::Publisher other;
  advertiseUnder(nh, argv[0], other);
  std::string topic;
  nh.param<std::string>("topic", topic, "scan");
  // a parameter's value joined to a suffix: neither the default alone nor
  // a name
  ros::Publisher filtered = nh.advertise<std_msgs::String>(topic + "_filtered", 1);
  ros::spin();
}
"""


@pytest.fixture(scope='module')
def node(tmp_path_factory):
    summary = analyze_source(
        tmp_path_factory.mktemp('names'), 'names', BUILT_NAMES)
    [node] = summary.nodes
    return node


def test_names_joined_from_known_strings_are_names(node):
    topics = {(p.topic, p.topic_is_literal) for p in node.publishers}
    assert {('turtle1/pose', True), ('~color', True),
            ('turtle1/cmd_vel', True)} <= topics
    assert [(s.topic, s.topic_is_literal) for s in node.subscribers] == [
        ('/turtle1/in', True)]


def test_names_joined_with_unknown_values_stay_unresolved(node):
    # before: the first variable's value stood for the whole name
    # ('turtle1'), and a parameter's default for `topic + "_filtered"`
    unknown = {p.topic: p.topic_param for p in node.publishers
               if not p.topic_is_literal}
    assert sorted(unknown) == ['robot+"/"+prefix', 'topic+"_filtered"']
    # two values joined, one of them unknown: no parameter makes the name
    assert unknown['robot+"/"+prefix'] is None


def test_a_parameter_joined_with_literals_keeps_them(node):
    # nh.param<std::string>("topic", topic, "scan"), then topic + "_filtered"
    param = next(p.topic_param for p in node.publishers
                 if p.topic == 'topic+"_filtered"')
    assert (param.name, param.default, param.prefix, param.suffix) == \
        ('topic', 'scan', '', '_filtered')


PRIVATE_PARAMETER_JOINED = r"""
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <string>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "cloud_filter");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::string input;
  pnh.param<std::string>("input", input, "points");
  ros::Publisher out = nh.advertise<sensor_msgs::PointCloud2>(
      input + "_filtered", 1);
  ros::spin();
}
"""


def test_the_launch_value_of_a_joined_parameter_makes_the_name(tmp_path):
    # ~input defaults to "points"; the code publishes input + "_filtered"
    summary = analyze_source(tmp_path, 'cloud_filter',
                             PRIVATE_PARAMETER_JOINED)
    [node] = summary.nodes
    assert _published(build_graph([summary]), node.id) == \
        {'/points_filtered'}
    # a launch file sets ~input: its value, with the suffix of the code
    launched = Instance(
        id='/cloud_filter', node=node, package=node.package,
        executable=node.executable, name='cloud_filter',
        params={'input': 'lidar'})
    assert _published(build_graph([summary], instances=[launched]),
                      '/cloud_filter') == {'/lidar_filtered'}


def _published(system, instance_id):
    return {entry['resolved']
            for entry in system.instances[instance_id].publishers}


HANDLE_AS_ARGUMENT = """
#include <ros/ros.h>
#include <message_filters/subscriber.h>
#include <realtime_tools/realtime_publisher.h>
#include <sensor_msgs/Imu.h>
#include <std_msgs/Float64.h>

void onImu(const sensor_msgs::Imu::ConstPtr &) {}

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "imu_filter");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  message_filters::Subscriber<sensor_msgs::Imu> imu_sub(pnh, "imu", 5);
  imu_sub.registerCallback(onImu);
  realtime_tools::RealtimePublisher<std_msgs::Float64> level_pub(nh, "level", 1);
  ros::spin();
  return 0;
}
"""


def test_a_nodehandle_given_as_an_argument_sets_the_namespace(tmp_path):
    summary = analyze_source(tmp_path, 'imu_filter', HANDLE_AS_ARGUMENT)
    [node] = summary.nodes
    # message_filters::Subscriber(pnh, ...) subscribes in the private
    # namespace, RealtimePublisher(nh, ...) in the node's
    assert [(s.topic, s.namespace) for s in node.subscribers] == [
        ('imu', '~')]
    assert [(p.topic, p.namespace) for p in node.publishers] == [
        ('level', '')]


HELPERS_OF_THE_PACKAGE = r"""
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>
#include <memory>
#include <string>
#include <utility>

// a helper class that subscribes with what its user gives it
class CommandInput
{
public:
  template <typename CallbackT>
  CommandInput(ros::NodeHandle& nh, const std::string& topic,
               CallbackT&& callback)
  {
    sub_ = nh.subscribe<std_msgs::String>(
        topic, 1, std::forward<CallbackT>(callback));
  }

private:
  ros::Subscriber sub_;
};

void advertiseStatus(ros::NodeHandle& nh, const std::string& name,
                     ros::Publisher& out)
{
  out = nh.advertise<std_msgs::Empty>(name, 1);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "commander");
  ros::NodeHandle nh;
  ros::Publisher echo = nh.advertise<std_msgs::String>("echo", 1);
  auto input = std::make_unique<CommandInput>(
      nh, "commands",
      [&echo](const std_msgs::String::ConstPtr& msg) { echo.publish(*msg); });
  ros::Publisher status;
  advertiseStatus(nh, "status", status);
  ros::spin();
}
"""


def test_helpers_of_the_package_take_what_their_callers_pass(tmp_path):
    # the topic and the callback are parameters of the helper: the one
    # call in the unit gives "commands" and the lambda of main (line 38)
    summary = analyze_source(tmp_path, 'commander', HELPERS_OF_THE_PACKAGE)
    [node] = summary.nodes
    assert [(s.topic, s.topic_is_literal, s.callback)
            for s in node.subscribers] == [
        ('commands', True, 'lambda@src/commander.cpp:38')]
    assert sorted((p.topic, p.topic_is_literal)
                  for p in node.publishers) == [
        ('echo', True), ('status', True)]
    # echo is published from the subscription's callback
    echo = next(p for p in node.publishers if p.topic == 'echo')
    assert echo.label == 'dependent'


HANDLES_MADE_FOR_EACH_CALL = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <memory>
#include <string>
#include <vector>

class Entity
{
public:
  explicit Entity(ros::NodeHandle nh)
  {
    pose_ = nh.advertise<std_msgs::String>("pose", 1);
  }

private:
  ros::Publisher pose_;
};

void announce(ros::NodeHandle& nh)
{
  static ros::Publisher status = nh.advertise<std_msgs::String>("status", 1);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "sim");
  ros::NodeHandle nh("fleet");
  std::vector<std::unique_ptr<Entity>> entities;
  for (int i = 0; i < 3; ++i) {
    entities.emplace_back(
        new Entity(ros::NodeHandle("entity" + std::to_string(i))));
  }
  announce(nh);
  ros::spin();
}
"""


def test_a_nodehandle_parameter_takes_the_namespace_its_callers_pass(
        tmp_path):
    summary = analyze_source(tmp_path, 'sim', HANDLES_MADE_FOR_EACH_CALL)
    [node] = summary.nodes
    by_topic = {p.topic: p for p in node.publishers}
    # announce(nh): the only caller passes the "fleet" handle
    assert by_topic['status'].namespace == 'fleet'
    # Entity(ros::NodeHandle("entity" + i)): a namespace the analysis cannot
    # compute; before, the parameter was taken for the root namespace
    assert by_topic['pose'].namespace.startswith('?')
    assert any("'pose'" in note and 'not know' in note
               for note in summary.diagnostics)


DEFAULT_HELD_BY_THE_VARIABLE = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <memory>
#include <string>

class Mapper : public rclcpp::Node
{
public:
  Mapper() : Node("mapper")
  {
    map_name_ = std::string("/map");
    map_name_ = this->declare_parameter("map_name", map_name_);
    scan_topic_ = "scan";
    scan_topic_ = this->declare_parameter("scan_topic", scan_topic_);
    frame_ = "odom";
    frame_ = this->get_parameter("frame").as_string();
    map_pub_ = create_publisher<std_msgs::msg::String>(map_name_, 1);
    scan_sub_ = create_subscription<std_msgs::msg::String>(
        scan_topic_, 1,
        [this](std_msgs::msg::String::ConstSharedPtr msg) { map_pub_->publish(*msg); });
    frame_pub_ = create_publisher<std_msgs::msg::String>(frame_, 1);
  }

private:
  std::string map_name_;
  std::string scan_topic_;
  std::string frame_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr map_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr frame_pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr scan_sub_;
};

int main(int argc, char** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Mapper>());
}
"""


def test_a_parameter_default_held_by_the_variable_it_sets(tmp_path):
    summary = analyze_source(tmp_path, 'mapper', DEFAULT_HELD_BY_THE_VARIABLE)
    [node] = summary.nodes
    params = {e.topic: e.topic_param and (e.topic_param.name,
                                          e.topic_param.default)
              for e in node.publishers + node.subscribers}
    # `x = "/map"; x = declare_parameter("map_name", x)`: the default is
    # the literal x held before the read
    assert params['map_name_'] == ('map_name', '/map')
    assert params['scan_topic_'] == ('scan_topic', 'scan')
    # overwritten by a value that is no parameter read with a default:
    # neither "odom" nor a guess
    assert params['frame_'] is None or params['frame_'][1] is None
    frame = next(p for p in node.publishers if p.topic == 'frame_')
    assert not frame.topic_is_literal


# the topic of an options object given to its constructor, also through a
# helper of the package (whose caller then names the topic)
OPTIONS_CONSTRUCTED = r"""
#include <ros/ros.h>

ros::Publisher advertiseRaw(ros::NodeHandle & nh, const std::string & topic)
{
  ros::AdvertiseOptions opts(topic, 10, "*", "*", "");
  opts.latch = true;
  return nh.advertise(opts);
}

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "raw");
  ros::NodeHandle nh;
  ros::AdvertiseOptions direct("status", 1, "*", "*", "");
  ros::Publisher status = nh.advertise(direct);
  ros::Publisher relayed = advertiseRaw(nh, "relayed");
  ros::spin();
  return 0;
}
"""


def test_the_topic_an_options_constructor_took(tmp_path):
    summary = analyze_source(tmp_path, 'raw', OPTIONS_CONSTRUCTED)
    [node] = summary.nodes
    # not the options variable's name (`direct`, `opts`)
    assert sorted(p.topic for p in node.publishers) == ['relayed', 'status']


HANDLES_RETURNED_BY_HELPERS = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <boost/shared_ptr.hpp>
#include <string>

class RobotLink
{
public:
  explicit RobotLink(const std::string& robot)
  {
    node_ = boost::shared_ptr<ros::NodeHandle>(new ros::NodeHandle(robot));
  }
  boost::shared_ptr<ros::NodeHandle>& node() { return node_; }

private:
  boost::shared_ptr<ros::NodeHandle> node_;
};

class ArmLink
{
public:
  ArmLink() : nh_("arm") {}
  ros::NodeHandle& handle() { return nh_; }

private:
  ros::NodeHandle nh_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "links");
  RobotLink link(argv[1]);
  ArmLink arm;
  ros::Publisher state =
      link.node()->advertise<std_msgs::String>("joint_states", 1);
  ros::Publisher grip = arm.handle().advertise<std_msgs::String>("grip", 1);
  ros::spin();
}
"""


def test_a_handle_a_package_function_returns_is_the_one_it_returns(
        tmp_path):
    summary = analyze_source(tmp_path, 'links', HANDLES_RETURNED_BY_HELPERS)
    [node] = summary.nodes
    by_topic = {p.topic: p for p in node.publishers}
    # node() returns node_, made with the command line's robot name: not
    # a namespace the analysis knows, never the node's own
    assert by_topic['joint_states'].namespace.startswith('?')
    # handle() returns nh_, made in the namespace "arm"
    assert by_topic['grip'].namespace == 'arm'


LITERAL_PARTS = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

void onCommand(const std_msgs::String::ConstPtr&) {}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "literal_parts");
  ros::NodeHandle nh;
  ros::Subscriber command = nh.subscribe(
      ros::names::append("controller", "command"), 1, onCommand);
  ros::Publisher state = nh.advertise<std_msgs::String>(
      std::string("arm") + "/state", 1);
  ros::spin();
}
"""


def test_names_joined_from_literals_only_are_names(tmp_path):
    summary = analyze_source(tmp_path, 'parts', LITERAL_PARTS)
    [node] = summary.nodes
    assert [(s.topic, s.topic_is_literal) for s in node.subscribers] == [
        ('controller/command', True)]
    assert [(p.topic, p.topic_is_literal) for p in node.publishers] == [
        ('arm/state', True)]
