# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The model mode's precompiled standard headers (model_mode/precompiled.py)."""

import os

from colcon_rsia.frontend.compile_db import find_resource_dir
from colcon_rsia.frontend.cpp.model_mode import precompiled
from colcon_rsia.package import analysis
from colcon_rsia.package import build_paths
from colcon_rsia.package import workers
import pytest

# std::deque and std::accumulate without their headers: the real rclcpp
# headers bring them in, the model's do not; only the precompiled standard
# headers declare them
NODE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>

class Averager : public rclcpp::Node
{
public:
  Averager() : Node("averager")
  {
    pub_ = create_publisher<std_msgs::msg::Float64>("average", 10);
    sub_ = create_subscription<std_msgs::msg::Float64>(
      "samples", 10, [this](std_msgs::msg::Float64::SharedPtr msg) {
        window_.push_back(msg->data);
        if (window_.size() > 10) {
          window_.pop_front();
        }
        std_msgs::msg::Float64 out;
        out.data = std::accumulate(window_.begin(), window_.end(), 0.0) /
          window_.size();
        pub_->publish(out);
      });
  }

private:
  std::deque<double> window_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::Float64>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Averager>());
  return 0;
}
"""


def _package(tmp_path):
    package = tmp_path / 'src' / 'averaging'
    (package / 'src').mkdir(parents=True)
    (package / 'src' / 'averager.cpp').write_text(NODE)
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(averaging)\n'
        'add_executable(averager src/averager.cpp)\n')
    return package


def _analyze(package, build_base, extra_arguments=()):
    return analysis.analyze_package(
        name='averaging', path=str(package), build_base=str(build_base),
        jobs=1, header_mode='model', use_cache=False,
        workspace_package_dirs=[str(package)],
        extra_arguments=list(extra_arguments))


def _assert_averager(summary):
    [unit] = summary.coverage.units
    # std::deque and std::accumulate came declared: nothing to repair
    assert (unit.package_errors, unit.repair_rounds) == (0, 0), \
        summary.diagnostics
    [node] = summary.nodes
    assert node.id == 'averaging/averager'
    [publisher] = node.publishers
    assert (publisher.topic, publisher.label) == ('average', 'dependent')
    assert [s.topic for s in node.subscribers] == ['samples']


@pytest.mark.parametrize('standard', ['c++14', 'c++17', 'gnu++20'])
def test_units_load_the_standard_headers_precompiled_for_their_standard(
        tmp_path, standard):
    package = _package(tmp_path)
    build_base = tmp_path / 'build' / 'averaging'
    summary = _analyze(package, build_base, [f'-std={standard}'])

    _assert_averager(summary)
    directory = build_paths.precompiled_dir(str(build_base))
    assert directory == str(tmp_path / 'build' / '.rsia' / 'precompiled')
    [pch] = os.listdir(directory)
    assert pch.startswith(f'std-{standard}-') and pch.endswith('.pch')


def test_a_precompiled_header_clang_refuses_gives_way_to_a_plain_parse(
        tmp_path):
    package = _package(tmp_path)
    build_base = tmp_path / 'build' / 'averaging'
    directory = build_paths.precompiled_dir(str(build_base))
    pch = precompiled.precompiled_header(
        directory, 'averager.cpp', ['-std=c++17'], find_resource_dir())
    assert os.path.isfile(pch)
    # what clang says of a PCH whose system headers changed since: no load
    with open(pch, 'wb') as h:
        h.write(b'not a precompiled header')

    summary = _analyze(package, build_base)

    # the unit parsed without it, with the model's lean standard headers:
    # std::deque and std::accumulate had to be repaired; the calls are found
    [unit] = summary.coverage.units
    assert unit.repair_rounds >= 1
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['average']
    assert [s.topic for s in node.subscribers] == ['samples']
    assert not os.path.exists(pch)
    # the next analysis (other processes, as the next run) builds it again
    precompiled._known.clear()
    workers.shutdown()
    _assert_averager(_analyze(package, build_base))
    assert os.path.isfile(pch)


@pytest.mark.parametrize('source, arguments, expected', [
    ('a.cpp', ['-std=c++14', '-DX'], 'c++14'),
    ('a.cpp', ['-std=c++14', '-std=gnu++17'], 'gnu++17'),
    ('a.cpp', ['-I', 'include'], ''),
    ('a.cpp', ['-x', 'c', '-std=c++17'], None),
    ('a.c', ['-std=gnu11'], None),
    ('a.cu', ['-std=c++17'], None),
])
def test_only_cxx_units_get_a_precompiled_header(
        tmp_path, source, arguments, expected):
    assert precompiled.language_standard(arguments) == (
        expected if source.endswith('.cpp') else None) or \
        not source.endswith('.cpp')
    pch = precompiled.precompiled_header(
        str(tmp_path), source, arguments, find_resource_dir())
    if expected is None:
        assert pch is None
    else:
        assert os.path.basename(pch).startswith(
            f'std-{expected or "default"}-')
