# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the sources use of libraries the model lacks, guessed before a parse.

Namespaces the sources add to, Qt reached through a library's headers,
boost::bind's placeholders, C libraries' prefixed names, befriended
classes. Expectations written by hand from the code below.
"""

from model_sources import assert_analyzes_clean


# a package adding overloads to a library's namespace (as a conversions
# header does): the library's own names it uses stay the library's
EXTENDED_NAMESPACE = r"""
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <grid/conversions.h>
#include <grid/GridHeader.h>

namespace grid
{
namespace io
{
inline int load(const std::string & file, sensor_msgs::PointCloud2 & cloud)
{
  grid::GridBlob blob;
  int result = grid::io::load(file, blob);
  grid::toMsg(blob, cloud);
  return result;
}
}  // namespace io

inline int version(int major = 1) { return major; }

template <typename T>
void fromMsg(const sensor_msgs::PointCloud2 & cloud, grid::Cloud<T> & out)
{
  grid::FieldMap map;
  grid::makeMapping<T>(cloud.fields, map);
  grid::GridHeader header;
  out.header = header;
}
}  // namespace grid

ros::Publisher pub;

void onCloud(const sensor_msgs::PointCloud2::ConstPtr & msg)
{
  grid::Cloud<grid::Cell> cells;
  grid::fromMsg(*msg, cells);
  sensor_msgs::PointCloud2 copy;
  grid::io::load("cells.bin", copy);
  copy.height = grid::version();
  pub.publish(copy);
}

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "cells");
  ros::NodeHandle nh;
  pub = nh.advertise<sensor_msgs::PointCloud2>("cells", 1);
  ros::Subscriber sub = nh.subscribe("cloud", 1, onCloud);
  ros::spin();
}
"""


def test_a_namespace_the_sources_add_to_keeps_the_librarys_names(tmp_path):
    # before: "no template named 'Cloud' in namespace 'grid'": a namespace
    # the sources open was left to them whole; then, declared, the
    # library's `grid::io::load` of another type would not be an overload
    # of theirs, nor `grid::GridHeader` the stand-in of its header (and
    # `grid::version()` is theirs alone)
    summary = assert_analyzes_clean(tmp_path, 'cells', EXTENDED_NAMESPACE)
    [node] = summary.nodes
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('cells', 'dependent')]
    assert [s.topic for s in node.subscribers] == ['cloud']


# an rviz panel: its base class's library includes Qt, the panel's own
# code uses Qt's classes and the moc macros without including Qt
QT_THROUGH_A_LIBRARY = r"""
#include <rviz_common/panel.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

namespace demo_panels
{
class Stamp : public rviz_common::Panel
{
  Q_OBJECT

public:
  explicit Stamp(QWidget * parent = nullptr) : rviz_common::Panel(parent)
  {
    label_ = new QLabel("stamp");
    QVBoxLayout * layout = new QVBoxLayout;
    layout->addWidget(label_);
  }

  void onInitialize() override
  {
    node_ = std::make_shared<rclcpp::Node>("stamp_panel");
    pub_ = node_->create_publisher<std_msgs::msg::String>("stamp", 1);
  }

protected Q_SLOTS:
  void onClicked()
  {
    std_msgs::msg::String msg;
    msg.data = label_->text().toStdString();
    pub_->publish(msg);
  }

private:
  QLabel * label_;
  rclcpp::Node::SharedPtr node_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace demo_panels
"""


def test_qt_used_through_a_library_header_is_declared(tmp_path):
    # before: "unknown type name 'QWidget'" (and Q_OBJECT): only the
    # panel library's real header includes Qt
    summary = assert_analyzes_clean(tmp_path, 'stamp', QT_THROUGH_A_LIBRARY)
    # (a panel no plugin export names is no node: its call is still read)
    assert [(site.api, site.line, site.origin)
            for site in summary.coverage.call_sites] == [
        ('create_publisher', 23, 'ast')]


# boost::bind's placeholders written bare, in a unit that includes no
# <boost/bind.hpp> itself: the real headers of its libraries do
BARE_PLACEHOLDERS = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <vendor_io/port.h>

class Echo
{
public:
  Echo()
  {
    pub_ = nh_.advertise<std_msgs::String>("echo", 1);
    sub_ = nh_.subscribe<std_msgs::String>(
      "words", 1, boost::bind(&Echo::onWord, this, _1));
  }

private:
  void onWord(const std_msgs::String::ConstPtr & word)
  {
    pub_.publish(*word);
  }

  ros::NodeHandle nh_;
  ros::Publisher pub_;
  ros::Subscriber sub_;
};

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "echo");
  Echo echo;
  ros::spin();
}
"""


def test_boost_binds_placeholders_written_bare_are_declared(tmp_path):
    # before: "use of undeclared identifier '_1'"
    summary = assert_analyzes_clean(tmp_path, 'echo', BARE_PLACEHOLDERS)
    [node] = summary.nodes
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('echo', 'dependent')]
    assert [s.topic for s in node.subscribers] == ['words']


# a C library the model lacks: its names carry its prefix, not a namespace
C_LIBRARY = r"""
#include <ros/ros.h>
#include <std_msgs/UInt32.h>
#include <scanlib.h>

class Reader
{
public:
  explicit Reader(ros::NodeHandle & nh)
  {
    pub_ = nh.advertise<std_msgs::UInt32>("packets", 10);
    handle_ = scanlib_open("eth0", errors_);
  }

  bool poll()
  {
    struct scanlib_header * header;
    const unsigned char * data;
    int scanlib_result = scanlib_next(handle_, &header, &data);
    if (scanlib_result != SCANLIB_OK) {
      return false;
    }
    std_msgs::UInt32 size;
    size.data = scanlib_result;
    pub_.publish(size);
    return true;
  }

private:
  ros::Publisher pub_;
  scanlib_t * handle_;
  char errors_[SCANLIB_ERRBUF_SIZE];
};

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "reader");
  ros::NodeHandle nh;
  Reader reader(nh);
  ros::Rate rate(100);
  while (ros::ok()) {
    reader.poll();
    rate.sleep();
  }
}
"""


def test_a_c_librarys_prefixed_names_are_declared(tmp_path):
    # before: "unknown type name 'scanlib_t'" (and the functions, the
    # constants): `<scanlib.h>` declares no namespace to guess from
    summary = assert_analyzes_clean(tmp_path, 'reader', C_LIBRARY)
    [node] = summary.nodes
    assert [(p.topic, p.label, p.pattern) for p in node.publishers] == [
        ('packets', 'independent', 'no_subscribers')]


# a class befriending an unknown library's class: `class ns::name` is a
# class whatever its case
BEFRIENDED = r"""
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <archive/access.hpp>

class Gauge
{
  friend class archive::access;

public:
  double value = 0.0;
};

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "gauge");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::Float64>("gauge", 1);
  Gauge gauge;
  ros::Rate rate(10);
  while (ros::ok()) {
    std_msgs::Float64 msg;
    msg.data = gauge.value;
    pub.publish(msg);
    rate.sleep();
  }
}
"""


def test_a_befriended_class_of_an_unknown_library_is_a_class(tmp_path):
    # before: "no class named 'access' in namespace 'archive'" (declared
    # as an object: a lower-case name)
    summary = assert_analyzes_clean(tmp_path, 'gauge', BEFRIENDED)
    [node] = summary.nodes
    assert [(p.topic, p.label, p.pattern) for p in node.publishers] == [
        ('gauge', 'independent', 'no_subscribers')]


# a stack's namespace the sources add to (`namespace corp {`), and one of
# its libraries the model lacks, included: the unit's own header of `corp`
# declares `corp::geometry_utils::` as nested, the library's header as a
# namespace of its own
NESTED_TWICE = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
#include <corp/geometry_utils/arc_length.hpp>

namespace corp
{
class Odometer : public rclcpp::Node
{
public:
  Odometer() : Node("odometer")
  {
    pub_ = create_publisher<std_msgs::msg::Float64>("distance", 1);
    timer_ = create_wall_timer(std::chrono::seconds(1), [this]() {
      std_msgs::msg::Float64 out;
      out.data = corp::geometry_utils::calcArcLength(points_);
      corp::geometry_utils::Polyline line;
      pub_->publish(out);
    });
  }

private:
  std::vector<double> points_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};
}  // namespace corp

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<corp::Odometer>());
}
"""


def test_a_namespace_guessed_twice_is_declared_once(tmp_path):
    # before: "redefinition of 'calcArcLength' as different kind of
    # symbol", "redefinition of 'Polyline'": the unit's header of `corp`
    # and the package's of `corp::geometry_utils` both declared them
    summary = assert_analyzes_clean(tmp_path, 'odometer', NESTED_TWICE)
    [node] = summary.nodes
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('distance', 'independent')]


# a message named but never included (the real headers of other messages
# include it), beside an unknown library: `builtin_interfaces::` was taken
# for a namespace that library's headers bring
IMPLICIT_MESSAGE = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/header.hpp>
#include <lanes/lanelet_map.hpp>

using Stamp = builtin_interfaces::msg::Time;

Stamp newer(const Stamp & a, const Stamp & b)
{
  return rclcpp::Time(a) > rclcpp::Time(b) ? a : b;
}

class Arbiter : public rclcpp::Node
{
public:
  Arbiter() : Node("arbiter")
  {
    pub_ = create_publisher<std_msgs::msg::Header>("latest", 1);
    sub_ = create_subscription<std_msgs::msg::Header>(
      "stamps", 1, [this](std_msgs::msg::Header::ConstSharedPtr msg) {
        std_msgs::msg::Header out = *msg;
        out.stamp = newer(msg->stamp, last_);
        lanes::LaneletMap map;
        pub_->publish(out);
      });
  }

private:
  Stamp last_;
  rclcpp::Publisher<std_msgs::msg::Header>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::Header>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Arbiter>());
}
"""


def test_a_message_named_but_not_included_is_its_stand_ins(tmp_path):
    # before: "definition of type 'Time' conflicts with type alias of the
    # same name": a catch-all `builtin_interfaces::msg::Time` beside the
    # message's stand-in
    summary = assert_analyzes_clean(tmp_path, 'arbiter', IMPLICIT_MESSAGE)
    [node] = summary.nodes
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('latest', 'dependent')]


# a header of the package that uses C's `assert` and includes only
# <vector>: with the real headers, a library's header included before it
# brings <cassert>
ASSERTING_HEADER = r"""
#pragma once
#include <vector>

inline double last(const std::vector<double> & samples)
{
  assert(!samples.empty());
  return samples.back();
}
"""

ASSERTING = r"""
#include <planning/samples.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("sampler");
  auto pub = node->create_publisher<std_msgs::msg::Float64>("last", 1);
  std_msgs::msg::Float64 out;
  out.data = last({1.0, 2.0});
  pub->publish(out);
}
"""


def test_cs_assert_used_without_its_header_is_declared(tmp_path):
    # before: "use of undeclared identifier 'assert'" in the header
    summary = assert_analyzes_clean(
        tmp_path, 'sampler', ASSERTING,
        headers={'include/planning/samples.hpp': ASSERTING_HEADER})
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['last']


# a library with a message-like header (`grid/GridCloud2.h`, its data
# type) beside its templates, used through a package header that never
# opens its namespace
MESSAGE_LIKE_HEADER = r"""
#pragma once
#include <grid/GridCloud2.h>
#include <grid/point_cloud.h>
#include <grid/point_types.h>

namespace mapper
{
using Cloud = grid::PointCloud<grid::PointXYZ>;
inline int size(const Cloud & cloud) { return cloud.width; }
}  // namespace mapper
"""

MESSAGE_LIKE = r"""
#include <ros/ros.h>
#include <std_msgs/Int32.h>
#include <mapper/cloud.hpp>

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "mapper");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::Int32>("size", 1);
  mapper::Cloud cloud;
  grid::GridCloud2 blob;
  std_msgs::Int32 out;
  out.data = mapper::size(cloud) + blob.height;
  pub.publish(out);
}
"""


def test_a_namespace_with_message_stand_ins_keeps_its_other_names(tmp_path):
    # before: an error in cloud.hpp, repaired only by one more parse: a
    # namespace with a message's stand-in was left to that stand-in whole
    summary = assert_analyzes_clean(
        tmp_path, 'mapper', MESSAGE_LIKE,
        headers={'include/mapper/cloud.hpp': MESSAGE_LIKE_HEADER})
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['size']


# a base class of the workspace returning a container of a library's type,
# and an override returning it by the library's alias of that container
SCENE_BASE = r"""
#pragma once
#include <vector>
#include <walls/wall.hpp>

namespace planner
{
class Scene
{
public:
  virtual ~Scene() = default;
  virtual std::vector<walls::Wall> createWalls() = 0;
};
}  // namespace planner
"""

OVERRIDE_ALIAS = r"""
#include <ros/ros.h>
#include <std_msgs/Int32.h>
#include <planner/scene.hpp>
#include <walls/walls.hpp>

namespace planner
{
class Crosswalk : public Scene
{
public:
  walls::Walls createWalls() override;
};

walls::Walls Crosswalk::createWalls()
{
  walls::Walls all;
  all.push_back(walls::Wall());
  return all;
}
}  // namespace planner

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "crosswalk");
  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<std_msgs::Int32>("walls", 1);
  planner::Crosswalk scene;
  std_msgs::Int32 out;
  out.data = scene.createWalls().size();
  pub.publish(out);
}
"""


def test_a_name_an_override_returns_is_what_the_base_returns(tmp_path):
    # before: "virtual function 'createWalls' has a different return type
    # ('walls::Walls') than the function it overrides (which has return
    # type 'std::vector<walls::Wall>')": the library's alias was guessed
    # as a class
    summary = assert_analyzes_clean(
        tmp_path, 'crosswalk', OVERRIDE_ALIAS,
        headers={'include/planner/scene.hpp': SCENE_BASE})
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['walls']
