# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Sources analyzed or parsed in model mode: helpers of tests/frontend/."""

import clang.cindex as ci
from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.compile_db import find_resource_dir
from colcon_rsia.frontend.cpp import model_mode
from colcon_rsia.frontend.cpp.model_mode.recovery import applied
from colcon_rsia.frontend.cpp.model_mode.recovery import edits as edit_rules
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.package import analysis
from conftest import analyze_source

# a ROS 2 node written against libraries the model does not have: OpenCV,
# Eigen, a base class from another library, a generated visibility header
DETECTOR = r"""
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <sensor_msgs/msg/image.hpp>
#include <opencv2/core.hpp>
#include <Eigen/Core>
#include <vision_core/filter_base.hpp>
#include "acme_vision/visibility_control.h"

namespace acme_vision
{

class ACME_VISION_PUBLIC Detector
  : public rclcpp::Node, public vision_core::FilterBase<float>
{
public:
  Detector() : Node("detector")
  {
    pub_ = create_publisher<std_msgs::msg::String>("detections", 10);
    sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image", 10,
      [this](sensor_msgs::msg::Image::ConstSharedPtr msg) { onImage(msg); });
  }

  void configure() override { threshold_ = CV_8UC1; }

private:
  void onImage(sensor_msgs::msg::Image::ConstSharedPtr msg)
  {
    cv::Mat_<float> kernel(3, 3);
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    geometry::shift(kernel, offset);
#if RSIA_TEST_VERSION_GTE(2, 0, 0)
    std_msgs::msg::String out;
    pub_->publish(out);
#endif
  }

  int threshold_ = 0;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr sub_;
};

}  // namespace acme_vision

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<acme_vision::Detector>());
  return 0;
}
"""

# a package acme_vision of one node, src/detector_node.cpp
ACME_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(acme_vision)
add_executable(detector_node src/detector_node.cpp)
"""


def acme_vision_package(tmp_path):
    """The package acme_vision of DETECTOR, under `tmp_path`/src."""
    package = tmp_path / 'src' / 'acme_vision'
    (package / 'src').mkdir(parents=True)
    (package / 'src' / 'detector_node.cpp').write_text(DETECTOR)
    (package / 'CMakeLists.txt').write_text(ACME_CMAKE)
    return package


def analyze_acme_vision(package, build_base, repair=analysis.REPAIR_ALWAYS):
    """The summary of the package acme_vision at `package`, in model mode."""
    # the tests of what repairs declare have them made whether or not the
    # facts need them (see test_repair_only_when_it_pays)
    return analysis.analyze_package(
        name='acme_vision', path=str(package), build_base=str(build_base),
        jobs=1, header_mode='model',
        workspace_package_dirs=[str(package)], repair=repair)


def analyze_one_unit(tmp_path, code):
    """The summary of a package of this one source, and its unit."""
    summary = analyze_source(
        tmp_path / 'src', 'acme_vision', code, file='src/detector_node.cpp',
        cmake=ACME_CMAKE, build_base=tmp_path / 'build' / 'acme_vision')
    [unit] = summary.coverage.units
    return summary, unit


def line_reader(text):
    """Read lines of `text` as the analysis reads a unit's lines."""
    lines = text.split('\n')

    def read_line(file, line):  # (as analysis.py's: '' past the end)
        return lines[line - 1] if 0 < line <= len(lines) else ''
    return read_line


def parse_unit(*, file, arguments, directory):
    """The translation unit of `file`, parsed with these arguments."""
    return cpp.parse(
        ci.Index.create(), file=str(file), arguments=arguments,
        resource_dir=find_resource_dir(), working_directory=str(directory))


def write_sources(tmp_path, **texts):
    """A package `pkg` with these files in src/: (package, [paths])."""
    package = tmp_path / 'src' / 'pkg'
    (package / 'src').mkdir(parents=True)
    paths = []
    for name, text in texts.items():
        paths.append(package / 'src' / f'{name}.cpp')
        paths[-1].write_text(text)
    return package, paths


def prepare_model_arguments(package, source, stub_dir):
    """The compiler arguments of `source` in model mode (C++17)."""
    return model_mode.prepare_model_arguments(
        source=str(source), arguments=['-std=gnu++17'],
        package_path=str(package), workspace_package_dirs=[],
        stub_dir=str(stub_dir))


def assert_analyzes_clean(tmp_path, package, code, headers=None):
    """A package of this one source parses clean the first time.

    Analysed as users do (repairs only where they pay), its one unit has
    no error and no repair round.

    :param headers: {path inside the package: text} written beside it
    :returns: the package summary
    """
    for path, text in (headers or {}).items():
        header = tmp_path / package / path
        header.parent.mkdir(parents=True, exist_ok=True)
        header.write_text(text)
    summary = analyze_source(tmp_path, package, code,
                             repair=analysis.REPAIR_WHEN_IT_PAYS)
    [unit] = summary.coverage.units
    assert (unit.errors, unit.repair_rounds) == (0, 0), summary.diagnostics
    return summary


def assert_parses_clean(tmp_path, code, repairs=()):
    """A package of this one source parses in model mode without errors.

    :param repairs: what the unit's repair header declares, if anything
    """
    package, [source] = write_sources(tmp_path, node=code)
    stub_dir = tmp_path / 'stubs'
    arguments = prepare_model_arguments(package, source, stub_dir)
    if repairs:
        header = store.repair_header(str(stub_dir), str(source))
        store.add_repairs(header, str(source), set(repairs))
        arguments = ['-include', header] + arguments
    tu = parse_unit(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


# a unit whose lambdas, casts and constants the in-memory edits change
EDITED_CODE = """\
double f(int i)
{
  const double a = [&]() {
    if (i > 0) {
      return 1.0;  // a { brace } in a comment
    }
    return g(i);
  }();
  auto b = [&] { return "}"[0] == 0 ? g(i) : 2.0; };
  int v[2] = {1, 2};
  if (i) {
    return v[0];
  }
  auto * const row = img.ptr<float>(i);
  constexpr double lowest = kmph2mps(10);
  return a;
}
struct Limits {
  static constexpr float max_angle = deg2rad(40.f);
};
"""


def edits_of(diagnostics, code=EDITED_CODE):
    """The edits of `code` (file a.cpp) for (message, line, column)s."""
    return edit_rules.edits_from_diagnostics(
        [(m, 'a.cpp', line, column) for m, line, column in diagnostics],
        lambda file: code)


def edited_text(edits, code=EDITED_CODE):
    """The text of `code` with `edits` made, and where they inserted."""
    [(text, insertions)] = applied.edited_files(
        edits, lambda file: code).values()
    return text.decode('latin-1'), insertions
