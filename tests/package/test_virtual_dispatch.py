# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Which override a virtual call runs, in nodelets sharing a base.

Filter::onInit calls childInit, which each filter overrides with its own
publisher; each nodelet's onInit calls Filter::onInit by its qualified
name. Expectations written from the files below (unbuilt, model mode).
"""

from colcon_rsia.package import analysis

FILTERS_CPP = """\
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

namespace filters
{
class Filter : public nodelet::Nodelet
{
protected:
  virtual void onInit()
  {
    nh_ = getNodeHandle();
    childInit(nh_);
  }
  virtual void childInit(ros::NodeHandle& nh) {}
  ros::NodeHandle nh_;
};

class Crop : public Filter
{
  void onInit() override { Filter::onInit(); }
  void childInit(ros::NodeHandle& nh) override
  {
    cropped_ = nh.advertise<std_msgs::String>("cropped", 1);
  }
  ros::Publisher cropped_;
};

class Blur : public Filter
{
  void onInit() override { Filter::onInit(); }
  void childInit(ros::NodeHandle& nh) override
  {
    blurred_ = nh.advertise<std_msgs::String>("blurred", 1);
  }
  ros::Publisher blurred_;
};
}  // namespace filters
PLUGINLIB_EXPORT_CLASS(filters::Crop, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(filters::Blur, nodelet::Nodelet)
"""
PLUGINS_XML = """\
<library path="lib/libfilters">
  <class name="filters/Crop" type="filters::Crop"
         base_class_type="nodelet::Nodelet"/>
  <class name="filters/Blur" type="filters::Blur"
         base_class_type="nodelet::Nodelet"/>
</library>
"""
PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>filters</name><version>0.0.1</version><description>x</description>
  <maintainer email="someone@example.com">someone</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>nodelet</depend>
  <export><nodelet plugin="${prefix}/nodelets.xml"/></export>
</package>
"""
CMAKE = """cmake_minimum_required(VERSION 3.10)
project(filters)
add_library(filters src/filters.cpp)
"""


def test_a_nodelet_runs_its_own_override_only(tmp_path):
    package = tmp_path / 'filters'
    (package / 'src').mkdir(parents=True)
    for name, text in (('src/filters.cpp', FILTERS_CPP),
                       ('nodelets.xml', PLUGINS_XML),
                       ('package.xml', PACKAGE_XML),
                       ('CMakeLists.txt', CMAKE)):
        (package / name).write_text(text)
    summary = analysis.analyze_package(
        name='filters', path=str(package), build_base=str(tmp_path / 'build'),
        jobs=1, header_mode='model', workspace_package_dirs=[str(package)])
    topics = {n.id: sorted(p.topic for p in n.publishers)
              for n in summary.nodes}
    # Filter::onInit's childInit(nh_) runs the override of the nodelet's
    # own class: a Crop never advertises Blur's topic
    assert topics == {'filters/Crop': ['cropped'],
                      'filters/Blur': ['blurred']}
