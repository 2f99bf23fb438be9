# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Facts read from tokens where the AST lost the calls.

Each unit here is parsed with none of the headers it includes, so clang
resolves no ROS call at all: every fact below must come from the tokens.
The expectations are written from the code of each test.
"""

import glob

import clang.cindex as ci
from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.cpp.token_facts import seconds_of
from colcon_rsia.summary.kinds import INDEPENDENT
from colcon_rsia.summary.kinds import ORIGIN_AST
from colcon_rsia.summary.kinds import ORIGIN_TOKENS
from colcon_rsia.summary.kinds import PATTERN_TIMER
from conftest import analyze_source
import pytest

TOKENS = ORIGIN_TOKENS


def _facts(tmp_path, text, name='node.cpp'):
    """The facts of `text` parsed with no include path at all.

    Not even the system's, where Debian's ROS 1 headers are.
    """
    source = tmp_path / name
    source.write_text(text)
    resource = sorted(glob.glob('/usr/lib/llvm-*/lib/clang/*'))[-1]
    tu = cpp.parse(ci.Index.create(), file=str(source),
                   arguments=['-x', 'c++', '-std=c++17', '-nostdinc'],
                   resource_dir=resource, working_directory=str(tmp_path))
    assert any('file not found' in d.spelling for d in tu.diagnostics)
    return cpp.extract_facts(tu, package_path=str(tmp_path), source=name)


def _name(facts, function_id):
    """A function's name, or its id when the unit has no body of it."""
    return next((f.name for f in facts.functions if f.id == function_id),
                function_id)


ROS2_NODE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
using namespace std::chrono_literals;
class Relay : public rclcpp::Node
{
public:
  Relay() : Node("relay")
  {
    pub_ = this->create_publisher<std_msgs::msg::String>("out", 10);
    sub_ = create_subscription<std_msgs::msg::String>(
      "in", 10, std::bind(&Relay::onMessage, this, std::placeholders::_1));
    timer_ = create_wall_timer(250ms, [this]() { status_->publish(make()); });
    status_ = create_publisher<std_msgs::msg::String>("status", 1);
  }

private:
  void onMessage(const std_msgs::msg::String::SharedPtr msg)
  {
    forward(*msg);
  }
  void forward(const std_msgs::msg::String & msg) { pub_->publish(msg); }
  std_msgs::msg::String make();
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, status_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Relay>());
}
"""


def test_ros2_endpoints_callbacks_and_calls_from_tokens(tmp_path):
    facts = _facts(tmp_path, ROS2_NODE)
    publishers = {p.topic: p for p in facts.publishers}
    assert set(publishers) == {'out', 'status'}
    out = publishers['out']
    assert (out.api, out.msg_type, out.topic_is_literal, out.origin,
            out.handle_name, out.location) == (
        'rclcpp::Node::create_publisher', 'std_msgs::msg::String', True,
        TOKENS, 'pub_', 'node.cpp:9')
    assert publishers['status'].location == 'node.cpp:13'
    [sub] = facts.subscribers
    assert (sub.topic, sub.msg_type, sub.origin, sub.location) == (
        'in', 'std_msgs::msg::String', TOKENS, 'node.cpp:10')
    assert _name(facts, sub.callback) == 'Relay::onMessage'
    [timer] = facts.timers
    # the lambda at line 12, column 39
    assert (timer.callback, timer.period, timer.rate_hz, timer.origin) == (
        'lambda@node.cpp:12:39', '250ms', 4.0, TOKENS)
    sites = {(s.location, s.function) for s in facts.publish_sites}
    forward = next(f.id for f in facts.functions
                   if f.name == 'Relay::forward')
    assert sites == {('node.cpp:12', 'lambda@node.cpp:12:39'),
                     ('node.cpp:21', forward)}
    # each publish site goes through the member its publisher is stored in
    by_handle = {p.handle: p.topic for p in facts.publishers}
    assert {by_handle[s.handle] for s in facts.publish_sites} == \
        {'out', 'status'}
    calls = {(_name(facts, c.caller), _name(facts, c.callee), c.kind)
             for c in facts.calls}
    assert ('Relay::onMessage', 'Relay::forward', 'call') in calls
    assert ('main', 'Relay::Relay', 'call') in calls
    # a callback is a root of its own, not called by its registrar
    assert not any(c.callee in (sub.callback, timer.callback)
                   for c in facts.calls)
    [name] = facts.node_names
    assert (name.name, name.location) == ('relay', 'node.cpp:7')


ROS1_LOOP = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
void onCommand(const std_msgs::String::ConstPtr & msg) {}
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "talker");
  ros::NodeHandle nh;
  ros::Publisher chatter = nh.advertise<std_msgs::String>("chatter", 10);
  ros::Subscriber sub = nh.subscribe("command", 1, onCommand);
  ros::Rate loop_rate(20);
  while (ros::ok()) {
    std_msgs::String msg;
    chatter.publish(msg);
    ros::spinOnce();
    loop_rate.sleep();
  }
}
"""


def test_ros1_rate_loop_from_tokens(tmp_path):
    facts = _facts(tmp_path, ROS1_LOOP)
    [publisher] = facts.publishers
    assert (publisher.topic, publisher.api, publisher.msg_type,
            publisher.handle_name) == (
        'chatter', 'ros::NodeHandle::advertise', 'std_msgs::String',
        'chatter')
    [subscriber] = facts.subscribers
    # the type from the callback's parameter, as written
    assert (subscriber.topic, subscriber.msg_type) == (
        'command', 'std_msgs::String')
    assert _name(facts, subscriber.callback) == 'onCommand'
    [rate] = facts.rates
    assert (rate.rate_hz, rate.location) == (20.0, 'node.cpp:10')
    [site] = facts.publish_sites
    assert site.handle == publisher.handle
    # the while loop at line 11: its id is its keyword's offset
    [loop] = site.loops
    [paced] = facts.paced_loops
    assert (paced.loop, paced.rate_handle, paced.sleep_location) == (
        loop, rate.handle, 'node.cpp:15')
    assert facts.node_names[0].name == 'talker'


def test_a_sleep_in_a_branch_paces_nothing(tmp_path):
    facts = _facts(tmp_path, ROS1_LOOP.replace(
        '    loop_rate.sleep();', '    if (slow) loop_rate.sleep();'))
    assert facts.rates and not facts.paced_loops


def test_the_ast_wins_where_it_has_the_call(tmp_path):
    # with the model headers every call resolves: no fact from tokens,
    # none twice
    summary = analyze_source(tmp_path, 'relay_pkg', ROS2_NODE)
    [node] = summary.nodes
    assert sorted(p.topic for p in node.publishers) == ['out', 'status']
    assert {p.origin for p in node.publishers} == {ORIGIN_AST}
    assert [s.origin for s in node.subscribers] == [ORIGIN_AST]


def test_a_call_resolved_to_another_library_is_not_taken(tmp_path):
    facts = _facts(tmp_path, """\
#include <ros/ros.h>
namespace mqtt { struct Client { void subscribe(const char *, int); }; }
void run(mqtt::Client & client, ros::NodeHandle & nh)
{
  client.subscribe("sensors/temperature", 1);
  ros::Subscriber s = nh.subscribe("scan", 1, onScan);
}
""")
    assert [s.topic for s in facts.subscribers] == ['scan']


def test_labels_evidence_and_coverage_say_what_came_from_tokens(tmp_path):
    # a statement no repair can mend (a syntax error) is dropped from the
    # AST; the tokens still show the publisher and its publish sites
    text = ROS2_NODE.replace(
        'status_ = create_publisher<std_msgs::msg::String>("status", 1);',
        'status_ = create_publisher<std_msgs::msg::String>("status", 1) + ;')
    summary = analyze_source(tmp_path, 'relay_pkg', text)
    [node] = summary.nodes
    publishers = {p.topic: p for p in node.publishers}
    status = publishers['status']
    assert (status.origin, status.label, status.pattern, status.rate_hz) == (
        ORIGIN_TOKENS, INDEPENDENT, PATTERN_TIMER, 4.0)
    assert publishers['out'].origin == ORIGIN_AST
    sites = [s for s in summary.coverage.call_sites
             if s.role == 'publisher']
    assert {(s.line, s.recorded, s.origin) for s in sites} == {
        (9, 'node', ORIGIN_AST), (13, 'node', ORIGIN_TOKENS)}


@pytest.mark.parametrize('written, seconds', [
    ('100ms', 0.1), ('2s', 2.0), ('std::chrono::milliseconds(50)', 0.05),
    ('ros::Duration(0.5)', 0.5), ('ros::Duration(1.0 / 20)', 0.05),
    ('rclcpp::Duration(1, 500000000)', 1.5),
    ('std::chrono::duration<double>(0.25)', 0.25),
    ('1.0 / rate_', None), ('period', None),
])
def test_periods_from_tokens(written, seconds):
    class Token:
        def __init__(self, text):
            self.text = text
    import re
    tokens = [Token(t) for t in re.findall(
        r'\d+\.?\d*(?:ms|us|ns|min|s|h)?|\w+|::|[()<>/,.*+-]', written)]
    value = seconds_of(tokens)
    if seconds is None:
        assert value is None
    else:
        assert value == pytest.approx(seconds)


SERIAL_PROTOCOL = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
template <class Packet>
class Channel
{
public:
  void configure(double frequency) { Packet::subscribe(frequency); }
};
void onCommand(const std_msgs::String::ConstPtr & msg) {}
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "base");
  ros::NodeHandle nh;
  ros::Subscriber command = nh.subscribe("command", 1, onCommand);
  ros::spin();
}
"""


def test_a_method_named_as_an_api_with_fewer_arguments_is_no_endpoint(
        tmp_path):
    # `Packet::subscribe(rate)`: a serial protocol's, on a template
    # parameter (the AST reads it by name) and from tokens alike
    summary = analyze_source(tmp_path / 'ast', 'base', SERIAL_PROTOCOL)
    [node] = summary.nodes
    assert [s.topic for s in node.subscribers] == ['command']
    facts = _facts(tmp_path, SERIAL_PROTOCOL)
    assert [s.topic for s in facts.subscribers] == ['command']


CONSTRUCTED = """\
#include <ros/ros.h>
class Node
{
public:
  Node(const Options & options, int queue);
  void start();
};
void run()
{
  Node node(load_options("config"), 3);
  node.start();
}
"""


def test_a_variable_made_by_its_constructor_runs_it(tmp_path):
    # the declaration fails (Options and load_options unknown): the
    # constructor, defined in another unit, is still what `run` calls
    facts = _facts(tmp_path, CONSTRUCTED)
    [run] = [f for f in facts.functions if f.name == 'run']
    callees = {c.callee for c in facts.calls if c.caller == run.id}
    # (clang's id of a constructor of class Node)
    assert [c for c in callees if '@S@Node@F@Node#' in c], callees


OUT_OF_CLASS_CONSTRUCTOR = """\
#include <ros/ros.h>
#include <nav_msgs/OccupancyGrid.h>
namespace mapping {
class Mapper {
 public:
  Mapper(double period);
 private:
  void Draw(const ros::WallTimerEvent&);
  ros::NodeHandle nh_;
  ros::Publisher grid_;
  ros::WallTimer timer_;
};

Mapper::Mapper(const double period)
    : grid_(nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true)),
      timer_(nh_.createWallTimer(ros::WallDuration(period),
                                 &Mapper::Draw, this)) {}

void Mapper::Draw(const ros::WallTimerEvent&) {
  grid_.publish(nav_msgs::OccupancyGrid());
}
}  // namespace mapping
"""


def test_an_out_of_class_constructors_initializers_from_tokens(tmp_path):
    facts = _facts(tmp_path, OUT_OF_CLASS_CONSTRUCTOR)
    # `Mapper::Mapper(...) : grid_(...)`: the initialiser list follows the
    # constructor's own name, not the class name that qualifies it
    [grid] = facts.publishers
    assert (grid.topic, grid.msg_type, grid.handle_name, grid.origin,
            grid.location) == (
        'map', 'nav_msgs::OccupancyGrid', 'grid_', TOKENS, 'node.cpp:15')
    [timer] = facts.timers
    assert (_name(facts, timer.callback), timer.location) == (
        'mapping::Mapper::Draw', 'node.cpp:16')


QT_TIMER_NODE = """\
#include <QTimer>
#include <QWidget>
#include <ros/ros.h>
#include <std_msgs/String.h>
class Panel : public QWidget
{
public:
  explicit Panel(ros::NodeHandle& nh)
  {
    pub_ = nh.advertise<std_msgs::String>("state", 1);
    timer_ = new QTimer(this);
    other_ = new QTimer(this);
    connect(timer_, &QTimer::timeout, this, &Panel::tick);
    connect(button_, &QPushButton::clicked, this, &Panel::tick);
    timer_->start(1000 / 15);
    other_->start(10);
  }
  void tick() { pub_.publish(std_msgs::String()); }
  QTimer* timer_;
  QTimer* other_;
  QPushButton* button_;
  ros::Publisher pub_;
};
"""


PACKAGE_CONNECT = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
class Link
{
public:
  explicit Link(ros::NodeHandle& nh) : nh_(nh)
  {
    connect(host_, 8080, 1.5);
  }
  void connect(const std::string& host, int port, double timeout)
  {
    status_ = nh_.advertise<std_msgs::String>("link_status", 1);
  }
  ros::NodeHandle nh_;
  ros::Publisher status_;
  std::string host_;
};
"""


def test_a_packages_own_connect_is_no_qt_connection(tmp_path):
    facts = _facts(tmp_path, PACKAGE_CONNECT)
    # `connect` by its name is Qt's only with QTimer's timeout(): this one
    # is the class's own method, which the constructor calls
    assert facts.timers == []
    calls = {(_name(facts, c.caller), _name(facts, c.callee))
             for c in facts.calls}
    assert ('Link::Link', 'Link::connect') in calls


def test_a_qtimer_connection_is_a_timer_at_its_start_interval(tmp_path):
    facts = _facts(tmp_path, QT_TIMER_NODE)
    # QTimer's timeout() only (a button's click is no clock), at the
    # interval its own start() gives: 1000/15 ms
    [timer] = facts.timers
    assert (_name(facts, timer.callback), timer.origin, timer.location) == (
        'Panel::tick', TOKENS, 'node.cpp:13')
    assert timer.rate_hz == pytest.approx(15.0)
