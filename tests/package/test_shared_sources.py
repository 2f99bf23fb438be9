# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A source built into an executable and into a nodelet library.

driver.cpp holds the driver class; the executable driver_node and the
nodelet library both build it. Both nodes run the driver and publish its
packets. Expectations written from the files below.
"""

from colcon_rsia.package import analysis

DRIVER_H = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
class Driver
{
public:
  Driver(ros::NodeHandle nh, ros::NodeHandle private_nh);
  bool poll();
private:
  ros::Publisher packets_;
};
"""
DRIVER_CPP = """\
#include "driver.h"
Driver::Driver(ros::NodeHandle nh, ros::NodeHandle private_nh)
{
  packets_ = nh.advertise<std_msgs::String>("packets", 10);
}
bool Driver::poll()
{
  packets_.publish(std_msgs::String());
  return true;
}
"""
NODE_CPP = """\
#include "driver.h"
int main(int argc, char ** argv)
{
  ros::init(argc, argv, "driver_node");
  ros::NodeHandle nh, private_nh("~");
  Driver driver(nh, private_nh);
  while (ros::ok() && driver.poll()) {
    ros::spinOnce();
  }
}
"""
NODELET_CPP = """\
#include <memory>
#include <thread>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include "driver.h"
class DriverNodelet : public nodelet::Nodelet
{
  void onInit() override
  {
    driver_.reset(new Driver(getNodeHandle(), getPrivateNodeHandle()));
    thread_ = std::thread([this]() { while (driver_->poll()) {} });
  }
  std::unique_ptr<Driver> driver_;
  std::thread thread_;
};
PLUGINLIB_EXPORT_CLASS(DriverNodelet, nodelet::Nodelet)
"""
PLUGINS_XML = """\
<library path="lib/libdriver_nodelet">
  <class name="driver/DriverNodelet" type="DriverNodelet"
         base_class_type="nodelet::Nodelet"/>
</library>
"""
PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>driver</name><version>0.0.1</version><description>x</description>
  <maintainer email="someone@example.com">someone</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>roscpp</depend><depend>nodelet</depend>
  <export><nodelet plugin="${prefix}/nodelets.xml"/></export>
</package>
"""
CMAKE = """cmake_minimum_required(VERSION 3.10)
project(driver)
add_executable(driver_node src/node.cpp src/driver.cpp)
add_library(driver_nodelet src/nodelet.cpp src/driver.cpp)
"""


def test_a_nodelet_runs_code_its_library_shares_with_an_executable(
        tmp_path):
    package = tmp_path / 'driver'
    (package / 'src').mkdir(parents=True)
    for name, text in (('src/driver.h', DRIVER_H),
                       ('src/driver.cpp', DRIVER_CPP),
                       ('src/node.cpp', NODE_CPP),
                       ('src/nodelet.cpp', NODELET_CPP),
                       ('nodelets.xml', PLUGINS_XML),
                       ('package.xml', PACKAGE_XML),
                       ('CMakeLists.txt', CMAKE)):
        (package / name).write_text(text)
    summary = analysis.analyze_package(
        name='driver', path=str(package), build_base=str(tmp_path / 'build'),
        jobs=1, header_mode='model', workspace_package_dirs=[str(package)])
    nodes = {n.id: n for n in summary.nodes}
    assert set(nodes) == {'driver/driver_node', 'driver/DriverNodelet'}
    for node in nodes.values():
        assert [(p.topic, p.publish_sites) for p in node.publishers] == [
            ('packets', ['src/driver.cpp:8'])], node.id


def test_a_call_reaches_the_one_definition_of_its_name():
    # node_main.cc calls Mapper's constructor as it declares it: with a
    # parameter type the model mode left undeclared there, the id spells
    # `int`; mapper.cc, repaired, defines it with the library's type. The
    # call reaches that definition (the only one of the name); a name
    # with two definitions (overloads) is not guessed
    from colcon_rsia.frontend.facts import Call
    from colcon_rsia.frontend.facts import Function
    from colcon_rsia.frontend.facts import TuFacts
    from colcon_rsia.package.node_facts import merge_facts
    main = TuFacts(source='node_main.cc', functions=[
        Function(id='c:@F@main#I#**C#', name='main',
                 location='node_main.cc:3')], calls=[
        Call(caller='c:@F@main#I#**C#',
             callee='c:@N@m@S@Mapper@F@Mapper#I#',
             location='node_main.cc:5'),
        Call(caller='c:@F@main#I#**C#',
             callee='c:@N@m@S@Mapper@F@run#I#',
             location='node_main.cc:6')])
    mapper = TuFacts(source='mapper.cc', functions=[
        Function(id='c:@N@m@S@Mapper@F@Mapper#*$@N@lib@S@Map#',
                 name='m::Mapper::Mapper', location='mapper.cc:4'),
        Function(id='c:@N@m@S@Mapper@F@run#d#', name='m::Mapper::run',
                 location='mapper.cc:9'),
        Function(id='c:@N@m@S@Mapper@F@run#f#', name='m::Mapper::run',
                 location='mapper.cc:12')])
    merged = merge_facts([main, mapper])
    assert [c.callee for c in merged.calls] == [
        'c:@N@m@S@Mapper@F@Mapper#*$@N@lib@S@Map#',
        'c:@N@m@S@Mapper@F@run#I#']
