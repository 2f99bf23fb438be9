# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A node class whose body has an error, constructed by another unit.

The class's constructor takes a type of a library the machine does not
have, and a method is annotated with that library's macro: its body has
errors. main.cpp makes the constructor's argument with that library, so
its ``std::make_shared<Mapper>(...)`` makes no call of the constructor,
although main.cpp itself has no endpoint call to lose.
"Repair only when it pays" must count that construction as a loss: the
node is the class's code. The class is built into a library, so
the executable's node reaches its code only through that call.
Expectations written from the files below (unbuilt, model mode, default
repair policy).
"""

from colcon_rsia.package import analysis

MAPPER_H = """\
#pragma once
#include <memory>
#include <mutex>
#include <ros/ros.h>
#include <std_msgs/String.h>

namespace mapping
{
class Mapper
{
public:
  Mapper(std::unique_ptr<gridlib::Builder> builder, double period);
  void Publish(const ros::TimerEvent& event) EXCLUDES(mutex_);

private:
  std::mutex mutex_;
  ros::NodeHandle nh_;
  ros::Publisher map_;
  ros::Timer timer_;
};
}  // namespace mapping
"""

MAPPER_CPP = """\
#include "mapper/mapper.h"

namespace mapping
{
Mapper::Mapper(std::unique_ptr<gridlib::Builder> builder, double period)
{
  map_ = nh_.advertise<std_msgs::String>("map", 1);
  timer_ = nh_.createTimer(ros::Duration(period), &Mapper::Publish, this);
}

void Mapper::Publish(const ros::TimerEvent&)
{
  std::lock_guard<std::mutex> lock(mutex_);
  map_.publish(std_msgs::String());
}
}  // namespace mapping
"""

MAIN_CPP = """\
#include <memory>
#include "mapper/mapper.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "mapper");
  auto builder = gridlib::CreateBuilder();
  auto mapper = std::make_shared<mapping::Mapper>(std::move(builder), 0.5);
  ros::spin();
}
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(mapper)
find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
catkin_package()
include_directories(include ${catkin_INCLUDE_DIRS})
add_library(mapper src/mapper.cpp)
add_executable(mapper_node src/main.cpp)
target_link_libraries(mapper_node mapper)
"""

PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="2">
  <name>mapper</name>
  <version>0.0.1</version>
  <description>A mapper</description>
  <maintainer email="a@b.c">A</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>roscpp</depend>
  <depend>std_msgs</depend>
</package>
"""


def test_a_node_class_with_an_error_in_its_body_is_still_constructed(
        tmp_path):
    package = tmp_path / 'mapper'
    (package / 'src').mkdir(parents=True)
    (package / 'include' / 'mapper').mkdir(parents=True)
    for name, text in (('include/mapper/mapper.h', MAPPER_H),
                       ('src/mapper.cpp', MAPPER_CPP),
                       ('src/main.cpp', MAIN_CPP),
                       ('package.xml', PACKAGE_XML),
                       ('CMakeLists.txt', CMAKE)):
        (package / name).write_text(text)
    summary = analysis.analyze_package(
        name='mapper', path=str(package), build_base=str(tmp_path / 'build'),
        jobs=1, header_mode='model', workspace_package_dirs=[str(package)])
    [node] = summary.nodes
    assert node.name == 'mapper'
    # the constructor advertises "map" and publishes it from its timer
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('map', 'independent')]
    # main.cpp was parsed again (the macro declared): it had lost the
    # construction
    units = {u.file: u for u in summary.coverage.units}
    assert units['src/main.cpp'].repair_rounds >= 1
