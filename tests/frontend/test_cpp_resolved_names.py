# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""C++ topic names the running node resolves from what the code shows.

A parameter's default held in a member passed on to a helper class, a
member's default initialiser overwritten only by the topic name of the
publisher it made, and names resolved by the ROS API (``resolveName``,
``expand_topic_or_service_name``). Expectations written by hand from the
code below: the node runs once, unnamespaced, under its default name.
"""

from colcon_rsia.system.graph import build_graph
from colcon_rsia.system.graph import Instance
from conftest import analyze_source

PASSED_TO_A_HELPER = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <memory>
#include <string>

class Saver
{
public:
  Saver(rclcpp::Node::SharedPtr node, const std::string & map_name)
  : node_(node), map_name_(map_name)
  {
    sub_ = node_->create_subscription<std_msgs::msg::String>(
      map_name_, 1, [](std_msgs::msg::String::ConstSharedPtr) {});
  }

private:
  rclcpp::Node::SharedPtr node_;
  std::string map_name_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};

class Mapper : public rclcpp::Node
{
public:
  Mapper() : Node("mapper") {}

  void setup()
  {
    map_name_ = std::string("/map");
    map_name_ = this->declare_parameter("map_name", map_name_);
    map_pub_ = create_publisher<std_msgs::msg::String>(map_name_, 1);
    meta_pub_ = create_publisher<std_msgs::msg::String>(
      map_name_ + "_metadata", 1);
    // by const reference: the helper cannot change map_name_
    saver_ = std::make_unique<Saver>(shared_from_this(), map_name_);
  }

private:
  std::string map_name_;
  std::unique_ptr<Saver> saver_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr map_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr meta_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Mapper>();
  node->setup();
  rclcpp::spin(node);
}
"""


def _resolved(summary):
    system = build_graph([summary])
    [instance] = system.instances.values()
    return {e['publisher'].location: e['resolved']
            for e in instance.publishers}, \
        {e['subscriber'].location: e['resolved']
         for e in instance.subscribers}


def test_a_parameter_default_passed_to_a_helper_names_its_topics(tmp_path):
    summary = analyze_source(tmp_path, 'mapper', PASSED_TO_A_HELPER)
    [node] = summary.nodes
    params = {e.location: (e.topic_param.name, e.topic_param.default,
                           e.topic_param.suffix)
              for e in node.publishers + node.subscribers if e.topic_param}
    # map_name_ = "/map" then declare_parameter("map_name", map_name_);
    # handing map_name_ to Saver by const reference sets nothing
    assert params['src/mapper.cpp:32'] == ('map_name', '/map', '')
    assert params['src/mapper.cpp:33'] == ('map_name', '/map', '_metadata')
    # Saver's map_name_ is its map_name parameter, which Mapper gives
    assert params['src/mapper.cpp:13'] == ('map_name', '/map', '')
    publishers, subscribers = _resolved(summary)
    assert publishers == {'src/mapper.cpp:32': '/map',
                          'src/mapper.cpp:33': '/map_metadata'}
    assert subscribers == {'src/mapper.cpp:13': '/map'}
    # a launch file's value of map_name wins over the default, everywhere
    launched = Instance(
        id='/mapper', node=node, package=node.package,
        executable=node.executable, name='mapper',
        params={'map_name': 'slam_map'})
    [instance] = build_graph([summary], instances=[launched]) \
        .instances.values()
    assert sorted(e['resolved'] for e in
                  instance.publishers + instance.subscribers) == [
        '/slam_map', '/slam_map', '/slam_map_metadata']


MEMBER_DEFAULTS = r"""
#include <rclcpp/rclcpp.hpp>
#include <nav_msgs/msg/odometry.hpp>
#include <std_msgs/msg/string.hpp>
#include <memory>
#include <string>

class PoseReporterPrivate
{
public:
  void OnUpdate() { pub_->publish(nav_msgs::msg::Odometry()); }

  rclcpp::Node::SharedPtr ros_node_;
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  std::string topic_name_{"odom"};
  std::string status_name_{"status"};
};

class PoseReporter
{
public:
  PoseReporter() : impl_(std::make_unique<PoseReporterPrivate>()) {}

  void Load(rclcpp::Node::SharedPtr node)
  {
    impl_->ros_node_ = node;
    impl_->pub_ = impl_->ros_node_->create_publisher<nav_msgs::msg::Odometry>(
      impl_->topic_name_, 1);
    // the name the publisher was made with, as the middleware resolved it
    impl_->topic_name_ = impl_->pub_->get_topic_name();
    impl_->status_pub_ = node->create_publisher<std_msgs::msg::String>(
      impl_->status_name_, 1);
    // the name of another publisher: no longer the member's default
    impl_->status_name_ = impl_->pub_->get_topic_name();
  }

  std::unique_ptr<PoseReporterPrivate> impl_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("pose_reporter");
  PoseReporter reporter;
  reporter.Load(node);
  rclcpp::TimerBase::SharedPtr timer = node->create_wall_timer(
    std::chrono::milliseconds(100),
    [&reporter]() { reporter.impl_->OnUpdate(); });
  rclcpp::spin(node);
}
"""


def test_a_member_default_overwritten_by_its_own_topic_name(tmp_path):
    summary = analyze_source(tmp_path, 'reporter', MEMBER_DEFAULTS)
    publishers, _ = _resolved(summary)
    # topic_name_{"odom"} is set again only to the name of the publisher
    # made with it; status_name_ to the name of another one: unknown
    assert publishers == {'src/reporter.cpp:28': '/odom',
                          'src/reporter.cpp:32': None}


EXPANDED_NAMES = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <memory>
#include <string>

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("relay");
  std::string in_topic = rclcpp::expand_topic_or_service_name(
    "in", node->get_name(), node->get_namespace());
  std::string out_topic = rclcpp::expand_topic_or_service_name(
    "out", node->get_name(), node->get_namespace());
  std::string echo_topic =
    node->get_node_topics_interface()->resolve_topic_name("~/echo");
  auto pub = node->create_publisher<std_msgs::msg::String>(out_topic, 1);
  auto echo = node->create_publisher<std_msgs::msg::String>(echo_topic, 1);
  auto sub = node->create_subscription<std_msgs::msg::String>(
    in_topic, 1,
    [&pub](std_msgs::msg::String::ConstSharedPtr msg) { pub->publish(*msg); });
  rclcpp::spin(node);
}
"""


def test_names_expanded_by_rclcpp_are_the_names_expanded(tmp_path):
    summary = analyze_source(tmp_path, 'relay', EXPANDED_NAMES)
    publishers, subscribers = _resolved(summary)
    assert publishers == {'src/relay.cpp:17': '/out',
                          'src/relay.cpp:18': '/relay/echo'}
    assert subscribers == {'src/relay.cpp:19': '/in'}


RESOLVED_BY_HANDLES = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

class Republisher
{
public:
  Republisher() : cloud_topic_("cloud"), pnh_("~")
  {
    // resolved in place: still the name "cloud" of nh_
    cloud_topic_ = nh_.resolveName(cloud_topic_);
  }

  void start()
  {
    cloud_pub_ = nh_.advertise<std_msgs::String>(cloud_topic_, 1);
  }

  ros::NodeHandle nh_;
  ros::NodeHandle pnh_;
  std::string cloud_topic_;
  ros::Publisher cloud_pub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "republish");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  std::string in_topic = nh.resolveName("in");
  std::string out_topic = nh.resolveName("out");
  // resolved by the private handle, used by the public one: private
  std::string debug_topic = pnh.resolveName("debug");
  ros::Publisher pub = nh.advertise<std_msgs::String>(out_topic, 1);
  ros::Publisher debug = nh.advertise<std_msgs::String>(debug_topic, 1);
  ros::Publisher direct = nh.advertise<std_msgs::String>(pnh.resolveName("direct"), 1);
  ros::Subscriber sub = nh.subscribe<std_msgs::String>(
      in_topic, 1, [&pub](const std_msgs::String::ConstPtr& m) { pub.publish(m); });
  Republisher republisher;
  republisher.start();
  ros::spin();
}
"""


def test_names_a_nodehandle_resolves_are_names_of_that_handle(tmp_path):
    summary = analyze_source(tmp_path, 'republish', RESOLVED_BY_HANDLES)
    publishers, subscribers = _resolved(summary)
    assert publishers == {'src/republish.cpp:17': '/cloud',
                          'src/republish.cpp:35': '/out',
                          'src/republish.cpp:36': '/republish/debug',
                          'src/republish.cpp:37': '/republish/direct'}
    assert subscribers == {'src/republish.cpp:38': '/in'}


NAMED_AFTER_THE_NODE = r"""
#include <ros/ros.h>
#include <actionlib/server/simple_action_server.h>
#include <actionlib_tutorials/FibonacciAction.h>
#include <std_msgs/String.h>
#include <string>

class FibonacciServer
{
public:
  FibonacciServer(std::string name)
  : as_(nh_, name, false), status_name_(name)
  {
    as_.registerGoalCallback([this]() { onGoal(); });
    as_.start();
    status_pub_ = nh_.advertise<std_msgs::String>(status_name_ + "/status", 1);
    // "/fibonacci" + "_count": no ROS name says that
    count_pub_ = nh_.advertise<std_msgs::String>(status_name_ + "_count", 1);
  }

  void onGoal()
  {
    as_.acceptNewGoal();
    status_pub_.publish(std_msgs::String());
  }

  ros::NodeHandle nh_;
  actionlib::SimpleActionServer<actionlib_tutorials::FibonacciAction> as_;
  std::string status_name_;
  ros::Publisher status_pub_;
  ros::Publisher count_pub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "fibonacci");
  FibonacciServer server(ros::this_node::getName());
  ros::spin();
}
"""


def test_the_node_name_names_what_is_under_it(tmp_path):
    summary = analyze_source(tmp_path, 'fibonacci', NAMED_AFTER_THE_NODE)
    publishers, _ = _resolved(summary)
    [instance] = build_graph([summary]).instances.values()
    # ros::this_node::getName() is /fibonacci: the action's goal and
    # cancel topics, and status_name_ + "/status", are under it
    assert sorted((e['subscriber'].location, e['resolved'])
                  for e in instance.subscribers) == [
        ('src/fibonacci.cpp:12', '/fibonacci/cancel'),
        ('src/fibonacci.cpp:12', '/fibonacci/goal')]
    assert publishers == {'src/fibonacci.cpp:16': '/fibonacci/status',
                          'src/fibonacci.cpp:18': None}


SET_BY_A_HELPER = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <string>

void withPrefix(std::string & name, const std::string & prefix)
{
  name = prefix + name;
}

class Mapper : public rclcpp::Node
{
public:
  Mapper(const std::string & prefix) : Node("mapper")
  {
    map_name_ = std::string("/map");
    map_name_ = this->declare_parameter("map_name", map_name_);
    // by non-const reference: the helper may change map_name_
    withPrefix(map_name_, prefix);
    map_pub_ = create_publisher<std_msgs::msg::String>(map_name_, 1);
  }

private:
  std::string map_name_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr map_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Mapper>(argv[1]));
}
"""


def test_a_variable_a_helper_may_set_keeps_no_default(tmp_path):
    summary = analyze_source(tmp_path, 'mapper', SET_BY_A_HELPER)
    [publisher] = summary.nodes[0].publishers
    assert publisher.topic_param is None or \
        publisher.topic_param.default is None
    assert _resolved(summary)[0] == {'src/mapper.cpp:20': None}


PARAMETER_EVENTS = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <memory>

class Tuner : public rclcpp::Node
{
public:
  Tuner() : Node("tuner")
  {
    pub_ = create_publisher<std_msgs::msg::String>("changes", 1);
    client_ = std::make_shared<rclcpp::AsyncParametersClient>(this);
    auto on_event =
      [this](const rcl_interfaces::msg::ParameterEvent::SharedPtr) {
        pub_->publish(std_msgs::msg::String());
      };
    events_ = client_->on_parameter_event(on_event);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::AsyncParametersClient::SharedPtr client_;
  rclcpp::Subscription<rcl_interfaces::msg::ParameterEvent>::SharedPtr events_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Tuner>());
}
"""


def test_a_parameter_client_subscribes_to_parameter_events(tmp_path):
    summary = analyze_source(tmp_path, 'tuner', PARAMETER_EVENTS)
    [node] = summary.nodes
    [subscriber] = node.subscribers
    assert (subscriber.topic, subscriber.location) == (
        '/parameter_events', 'src/tuner.cpp:17')
    assert subscriber.msg_type == 'rcl_interfaces::msg::ParameterEvent'
    # the lambda the variable holds runs per event, and publishes
    assert subscriber.callback == 'lambda@src/tuner.cpp:14'
    [publisher] = node.publishers
    assert publisher.label == 'dependent'


HANDLES_OF_ANOTHER_LIBRARY = r"""
#include <ros/ros.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <std_msgs/String.h>
#include <lazy_tools/lazy_nodelet.h>

namespace demo
{
// pnh_ comes from a base class of a library the unit cannot read
class Reader : public lazy_tools::LazyNodelet
{
public:
  void onInit()
  {
    LazyNodelet::onInit();
    pub_ = pnh_->advertise<std_msgs::String>("output", 1);
    sub_ = pnh_->subscribe("input", 1, &Reader::cb, this);
    absolute_ = pnh_->advertise<std_msgs::String>("/absolute", 1);
  }
  void cb(const std_msgs::String::ConstPtr& m) { pub_.publish(m); }
  ros::Publisher pub_;
  ros::Publisher absolute_;
  ros::Subscriber sub_;
};
}
PLUGINLIB_EXPORT_CLASS(demo::Reader, nodelet::Nodelet)
"""


def test_a_handle_of_another_library_has_no_namespace_known(tmp_path):
    summary = analyze_source(tmp_path, 'reader', HANDLES_OF_ANOTHER_LIBRARY)
    publishers, subscribers = _resolved(summary)
    # relative to a namespace the library's code gives pnh_: not the root
    assert publishers == {'src/reader.cpp:17': None,
                          'src/reader.cpp:19': '/absolute'}
    assert subscribers == {'src/reader.cpp:18': None}
    assert any("'output' is relative to the NodeHandle namespace 'pnh_'"
               in note for note in summary.diagnostics)


MEMBER_HELD_DEFAULTS = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <memory>
#include <string>

class Echo : public rclcpp::Node
{
public:
  Echo() : Node("echo"), in_("chatter")
  {
    this->get_parameter_or("in", in_, in_);
    out_ = this->declare_parameter("out", out_);
    pub_ = create_publisher<std_msgs::msg::String>(out_, 1);
    sub_ = create_subscription<std_msgs::msg::String>(
      in_, 1,
      [this](std_msgs::msg::String::ConstSharedPtr msg) { pub_->publish(*msg); });
  }

private:
  std::string in_;
  std::string out_{"echoed"};
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Echo>());
}
"""


def test_defaults_held_by_members_before_the_read(tmp_path):
    summary = analyze_source(tmp_path, 'echo', MEMBER_HELD_DEFAULTS)
    [node] = summary.nodes
    # in_("chatter") in the initialiser list, out_{"echoed"} in the class
    assert {(e.topic_param.name, e.topic_param.default)
            for e in node.publishers + node.subscribers} == {
        ('in', 'chatter'), ('out', 'echoed')}
    publishers, subscribers = _resolved(summary)
    assert publishers == {'src/echo.cpp:14': '/echoed'}
    assert subscribers == {'src/echo.cpp:15': '/chatter'}
