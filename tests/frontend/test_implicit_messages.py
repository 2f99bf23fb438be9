# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""ROS 2 messages a unit names before including them, or never (model mode).

A real message header includes the headers of its fields' types, so code
that includes `path.hpp` may name the `Point` of its fields, and every
`std_msgs::msg::Header` brings `builtin_interfaces::msg::Time`. The model's
stand-ins of message headers include nothing; the model declares such
messages for the unit that names them.
"""

import os

from colcon_rsia.frontend.cpp import model_mode
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR
from colcon_rsia.package import analysis
from model_sources import assert_analyzes_clean
from model_sources import write_sources

# an interface package of any name (no `_msgs` suffix), and
# builtin_interfaces, named and not included
NAMED_NOT_INCLUDED = r"""
#include <memory>
#include <vector>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"
#include "route_tools/msg/route.hpp"

class Checker : public rclcpp::Node
{
public:
  Checker() : Node("checker")
  {
    pub_ = create_publisher<std_msgs::msg::String>("checked", 10);
    sub_ = create_subscription<route_tools::msg::Route>(
      "route", 1,
      [this](route_tools::msg::Route::ConstSharedPtr msg) { onRoute(*msg); });
  }

private:
  bool stale(const builtin_interfaces::msg::Time & stamp) const
  {
    return (now() - rclcpp::Time(stamp)).seconds() > 1.0;
  }
  void onRoute(const route_tools::msg::Route & route)
  {
    std::vector<route_tools::msg::Waypoint> points = route.points;
    if (stale(route.header.stamp)) {
      return;
    }
    std_msgs::msg::String out;
    out.data = std::to_string(points.size());
    pub_->publish(out);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<route_tools::msg::Route>::SharedPtr sub_;
};
"""


def test_messages_of_any_interface_package_are_declared(tmp_path):
    # before: "use of undeclared identifier 'builtin_interfaces'" and
    # "no member named 'Waypoint' in namespace 'route_tools::msg'"
    assert_analyzes_clean(tmp_path, 'checker', NAMED_NOT_INCLUDED)


# a header of the package names Waypoint through the Route it includes;
# the unit includes Waypoint's own header only after it
SHIFT_HEADER = r"""
#pragma once
#include <vector>
#include "route_msgs/msg/route.hpp"

namespace routes
{
using route_msgs::msg::Waypoint;
std::vector<Waypoint> shifted(const route_msgs::msg::Route & route);
}  // namespace routes
"""
SHIFT_SOURCE = r"""
#include "routes/shift.hpp"
#include "route_msgs/msg/waypoint.hpp"

namespace routes
{
std::vector<Waypoint> shifted(const route_msgs::msg::Route & route)
{
  std::vector<Waypoint> points = route.points;
  return points;
}
}  // namespace routes
"""


def test_a_message_named_before_its_include_is_declared(tmp_path):
    # before: the unit includes waypoint.hpp, so it was not declared
    # early: "no member named 'Waypoint' in namespace 'route_msgs::msg'"
    assert_analyzes_clean(tmp_path, 'routes', SHIFT_SOURCE, headers={
        'include/routes/shift.hpp': SHIFT_HEADER})


# a library's own `msg` namespace, hand-written: no interface package
OWN_MSG_HEADER = r"""
#pragma once
#include <cstdint>

namespace canbus
{
namespace msg
{
struct Frame
{
  uint32_t id;
};
}  // namespace msg
}  // namespace canbus
"""
OWN_MSG_SOURCE = r"""
#include "std_msgs/msg/string.hpp"
#include "canbus/frame.hpp"

std_msgs::msg::String describe(const canbus::msg::Frame & frame)
{
  std_msgs::msg::String text;
  text.data = std::to_string(frame.id);
  return text;
}
"""


def test_a_namespace_the_code_opens_is_not_an_interface_package(tmp_path):
    # a stand-in of canbus/msg/frame.hpp would redefine canbus::msg::Frame
    assert_analyzes_clean(tmp_path, 'canbus', OWN_MSG_SOURCE, headers={
        'include/canbus/frame.hpp': OWN_MSG_HEADER})


# an interface's C header (rosidl generates one beside the C++ one),
# included by C++ code that uses the C++ message
C_HEADER_SOURCE = r"""
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/point_cloud2.h>
#include <sensor_msgs/msg/point_cloud2.hpp>

class Cropper : public rclcpp::Node
{
public:
  Cropper() : Node("cropper")
  {
    pub_ = create_publisher<sensor_msgs::msg::PointCloud2>("cropped", 1);
    sub_ = create_subscription<sensor_msgs::msg::PointCloud2>(
      "points", 1,
      [this](sensor_msgs::msg::PointCloud2::ConstSharedPtr cloud) {
        pub_->publish(*cloud);
      });
  }

private:
  rclcpp::Publisher<sensor_msgs::msg::PointCloud2>::SharedPtr pub_;
  rclcpp::Subscription<sensor_msgs::msg::PointCloud2>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Cropper>());
}
"""


def test_an_interfaces_c_header_declares_no_library_namespace(tmp_path):
    # before: `sensor_msgs/msg/` was taken for a library's directory below
    # a model namespace, and its stand-in declared `PointCloud2` a class
    # again: "definition of type 'PointCloud2' conflicts with type alias
    # of the same name"
    summary = assert_analyzes_clean(tmp_path, 'cropper', C_HEADER_SOURCE)
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['cropped']


# model names that a library header brings: tf2's getYaw after
# tf2_geometry_msgs (tf2/utils.h in the real headers), and rclcpp itself
# after an unmodelled library's header, which the unit includes alone
BROUGHT_BY_OTHER_HEADERS = r"""
#include <tf2_geometry_msgs/tf2_geometry_msgs.hpp>
#include <geometry_msgs/msg/pose_stamped.hpp>
#include <std_msgs/msg/float64.hpp>
#include <corp_tools/node_base.hpp>

class Heading : public rclcpp::Node
{
public:
  Heading() : Node("heading")
  {
    pub_ = create_publisher<std_msgs::msg::Float64>("yaw", 1);
    sub_ = create_subscription<geometry_msgs::msg::PoseStamped>(
      "pose", 1, [this](geometry_msgs::msg::PoseStamped::ConstSharedPtr pose) {
        std_msgs::msg::Float64 yaw;
        yaw.data = tf2::getYaw(pose->pose.orientation);
        pub_->publish(yaw);
      });
  }

private:
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
  rclcpp::Subscription<geometry_msgs::msg::PoseStamped>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Heading>());
}
"""


def test_model_names_other_headers_bring_are_declared(tmp_path):
    # before: "no member named 'getYaw' in namespace 'tf2'" and "use of
    # undeclared identifier 'rclcpp'"
    summary = assert_analyzes_clean(tmp_path, 'heading',
                                    BROUGHT_BY_OTHER_HEADERS)
    [node] = summary.nodes
    assert [(p.topic, p.msg_type) for p in node.publishers] == [
        ('yaw', 'std_msgs::msg::Float64')]
    assert [s.topic for s in node.subscribers] == ['pose']


# a class that a library's ROS 1 and ROS 2 model headers both declare
# (image_transport/publisher.h and publisher.hpp), reached through the
# unit's own include
BOTH_VERSIONS = r"""
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <image_transport/image_transport.hpp>
#include <sensor_msgs/msg/image.hpp>

class Relay : public rclcpp::Node
{
public:
  Relay() : Node("relay")
  {
    pub_ = image_transport::create_publisher(this, "out");
  }

private:
  image_transport::Publisher pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Relay>());
}
"""


def test_a_model_name_its_include_declares_is_not_declared_again(tmp_path):
    # before: the ROS 1 header was included too: "redefinition of
    # 'Publisher'"
    summary = assert_analyzes_clean(tmp_path, 'relay', BOTH_VERSIONS)
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['out']


# two units of one package: a library file without a ROS 2 include of its
# own, naming diagnostic_updater's class, and a ROS 2 node including the
# library's ROS 2 header
LIBRARY_UNIT = r"""
#include <corp_driver/status.hpp>

void fill(diagnostic_updater::DiagnosticStatusWrapper & status)
{
  status.summary(0, "ok");
}
"""
NODE_UNIT = r"""
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <diagnostic_updater/diagnostic_updater.hpp>
#include <std_msgs/msg/string.hpp>

class Monitor : public rclcpp::Node
{
public:
  Monitor() : Node("monitor"), updater_(this)
  {
    pub_ = create_publisher<std_msgs::msg::String>("state", 1);
  }

private:
  diagnostic_updater::Updater updater_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""


def test_a_model_header_named_by_one_unit_is_included_by_it_alone(tmp_path):
    # before: the library unit's early header (the ROS 1 one: it has no
    # ROS 2 include) went to every unit of the package; the node then
    # had both versions: "redefinition of 'DiagnosticStatusWrapper'"
    package, _ = write_sources(tmp_path, a_library=LIBRARY_UNIT,
                               node=NODE_UNIT)
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(pkg)\n'
        'add_library(status src/a_library.cpp)\n'
        'add_executable(monitor src/node.cpp)\n')
    summary = analysis.analyze_package(
        name='pkg', path=str(package), build_base=str(tmp_path / 'build'),
        jobs=1, header_mode='model', workspace_package_dirs=[str(package)],
        repair=analysis.REPAIR_WHEN_IT_PAYS)
    units = {u.file: u for u in summary.coverage.units}
    assert units['src/node.cpp'].errors == 0, summary.diagnostics
    assert units['src/a_library.cpp'].errors == 0, summary.diagnostics


def test_the_workspaces_copy_of_a_model_header_is_not_included_first(
        tmp_path):
    # the library itself is in the workspace (its real headers declare
    # what they declare): the unit names tf2::getYaw, which its own
    # tf2/utils.h declares, but never includes it
    package, [source] = write_sources(tmp_path, node=(
        '#include <corp_driver/pose.hpp>\n'
        'double yaw(const corp_driver::Pose & pose)\n'
        '{\n  return tf2::getYaw(pose.orientation);\n}\n'))
    own = package / 'include' / 'tf2' / 'utils.h'
    own.parent.mkdir(parents=True)
    own.write_text('#pragma once\nnamespace tf2 {\n'
                   'template <class A> double getYaw(const A & a);\n}\n')
    arguments = model_mode.prepare_model_arguments(
        source=str(source),
        arguments=['-std=gnu++17', '-I' + str(package / 'include')],
        package_path=str(package), workspace_package_dirs=[str(package)],
        stub_dir=str(tmp_path / 'stubs'))
    first = [arguments[i + 1] for i, a in enumerate(arguments[:-1])
             if a == '-include']
    assert not [f for f in first if f.endswith('tf2/utils.h')]
    # without the copy, the model's is
    own.unlink()
    arguments = model_mode.prepare_model_arguments(
        source=str(source),
        arguments=['-std=gnu++17', '-I' + str(package / 'include')],
        package_path=str(package), workspace_package_dirs=[str(package)],
        stub_dir=str(tmp_path / 'stubs2'))
    assert os.path.join(MODEL_HEADERS_DIR, 'tf2', 'utils.h') in arguments
