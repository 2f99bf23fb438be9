# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A nodelet deriving from nodelet_topic_tools::NodeletLazy.

Its base's advertise<M>(nh, topic, queue) makes its publishers; the base
calls the nodelet's subscribe() when the first subscriber connects, where
the nodelet subscribes to its input and publishes in that callback.
Expectations written from the files below; unbuilt (model mode), as the
Debian ROS 1 packages have no nodelet_topic_tools.
"""

from colcon_rsia.package import analysis

NODELET_CPP = """\
#include <nodelet_topic_tools/nodelet_lazy.h>
#include <pluginlib/class_list_macros.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/String.h>

namespace cloud
{
class Crop : public nodelet_topic_tools::NodeletLazy
{
  void onInit() override
  {
    NodeletLazy::onInit();
    pub_output_ = advertise<sensor_msgs::PointCloud2>(*pnh_, "output", 1);
    pub_status_ = advertise<std_msgs::String>(*nh_, "crop_status", 1, true);
    onInitPostProcess();
  }
  void subscribe() override
  {
    sub_input_ = pnh_->subscribe("input", 1, &Crop::input, this);
  }
  void unsubscribe() override { sub_input_.shutdown(); }
  void input(const sensor_msgs::PointCloud2::ConstPtr& cloud)
  {
    pub_output_.publish(*cloud);
  }
  ros::Publisher pub_output_, pub_status_;
  ros::Subscriber sub_input_;
};
}  // namespace cloud
PLUGINLIB_EXPORT_CLASS(cloud::Crop, nodelet::Nodelet)
"""
PLUGINS_XML = """\
<library path="lib/libcloud">
  <class name="cloud/Crop" type="cloud::Crop"
         base_class_type="nodelet::Nodelet"/>
</library>
"""
PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>cloud</name><version>0.0.1</version><description>x</description>
  <maintainer email="someone@example.com">someone</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>nodelet</depend><depend>nodelet_topic_tools</depend>
  <export><nodelet plugin="${prefix}/nodelets.xml"/></export>
</package>
"""
CMAKE = """cmake_minimum_required(VERSION 3.10)
project(cloud)
add_library(cloud src/crop.cpp)
"""


def _analyze(tmp_path, header_mode):
    """The nodelet package written under `tmp_path`, analysed unbuilt."""
    package = tmp_path / 'cloud'
    (package / 'src').mkdir(parents=True)
    for name, text in (('src/crop.cpp', NODELET_CPP),
                       ('nodelets.xml', PLUGINS_XML),
                       ('package.xml', PACKAGE_XML),
                       ('CMakeLists.txt', CMAKE)):
        (package / name).write_text(text)
    return analysis.analyze_package(
        name='cloud', path=str(package), build_base=str(tmp_path / 'build'),
        jobs=1, header_mode=header_mode,
        workspace_package_dirs=[str(package)])


def test_a_lazy_nodelets_base_advertises_and_its_subscribe_runs(tmp_path):
    summary = _analyze(tmp_path, 'model')
    [node] = summary.nodes
    assert node.id == 'cloud/Crop'
    by_topic = {p.topic: p for p in node.publishers}
    assert set(by_topic) == {'output', 'crop_status'}
    output = by_topic['output']
    assert (output.msg_type, output.location) == (
        'sensor_msgs::PointCloud2', 'src/crop.cpp:13')
    # published in the callback of the input subscribe() makes: dependent
    assert (output.label, output.publish_sites) == (
        'dependent', ['src/crop.cpp:24'])
    # never published: no publish site says what drives it
    assert by_topic['crop_status'].publish_sites == []
    [sub] = node.subscribers
    assert (sub.topic, sub.callback, sub.location) == (
        'input', 'cloud::Crop::input', 'src/crop.cpp:19')
    # every advertise and subscribe of the package is the nodelet's
    assert {(c.line, c.recorded) for c in summary.coverage.call_sites} == {
        (13, 'node'), (14, 'node'), (19, 'node')}


def test_without_the_bases_header_the_tokens_name_its_topics(tmp_path):
    # the exact mode uses the machine's headers: nodelet_topic_tools's is
    # missing, the class has no base the parse knows, and the calls are
    # read from tokens. `advertise` called on the nodelet itself is its
    # base's (handle first, then topic), not a NodeHandle's
    summary = _analyze(tmp_path, 'exact')
    [node] = summary.nodes
    assert sorted((p.topic, p.location) for p in node.publishers) == [
        ('crop_status', 'src/crop.cpp:14'), ('output', 'src/crop.cpp:13')]
    assert [s.topic for s in node.subscribers] == ['input']
