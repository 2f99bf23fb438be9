# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Code that makes its own types ROS 1 messages parses without repairs.

roscpp lets a type be published as a message when the code specialises the
message traits, the serializer and the printer of ``ros::message_traits``,
``ros::serialization`` and ``ros::message_operations`` (as generated
message headers do). The model headers have those templates, so that the
specialisations are no errors; its static assertions on values the model
cannot know (a message's checksum) check nothing.
"""

from conftest import analyze_source

CUSTOM_MESSAGE = r"""
#include <ros/ros.h>
#include <ros/static_assert.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/distortion_models.h>

namespace acme
{
struct Frame
{
  std_msgs::Header header;
  std::vector<unsigned char> pixels;
  // a header of constants only, read as a message stand-in
  bool plumb_bob(const sensor_msgs::CameraInfo & info) const
  {
    return info.distortion_model == sensor_msgs::distortion_models::PLUMB_BOB;
  }
};
}  // namespace acme

namespace ros
{
namespace message_traits
{
template<> struct MD5Sum<acme::Frame>
{
  static const char * value() { return MD5Sum<sensor_msgs::Image>::value(); }
  static const char * value(const acme::Frame &) { return value(); }
  static const uint64_t static_value1 =
    MD5Sum<sensor_msgs::Image>::static_value1;
  ROS_STATIC_ASSERT(MD5Sum<sensor_msgs::Image>::static_value1 ==
                    0x060021388200f6f0ULL);
};
template<> struct DataType<acme::Frame>
{
  static const char * value() { return DataType<sensor_msgs::Image>::value(); }
  static const char * value(const acme::Frame &) { return value(); }
};
template<> struct HasHeader<acme::Frame> : TrueType {};
}  // namespace message_traits

namespace serialization
{
template<> struct Serializer<acme::Frame>
{
  template<typename Stream>
  inline static void write(Stream & stream, const acme::Frame & m)
  {
    stream.next(m.header);
    stream.next(static_cast<uint32_t>(m.pixels.size()));
  }
  inline static uint32_t serializedLength(const acme::Frame & m)
  {
    return serializationLength(m.header) + 4 + m.pixels.size();
  }
};
}  // namespace serialization
}  // namespace ros

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "framer");
  ros::NodeHandle nh;
  ros::Publisher frames = nh.advertise<acme::Frame>("frames", 1);
  ros::Rate rate(15);
  while (ros::ok())
  {
    frames.publish(acme::Frame());
    rate.sleep();
  }
  return 0;
}
"""


def test_a_type_made_a_message_by_its_traits_parses_cleanly(tmp_path):
    summary = analyze_source(tmp_path, 'framer', CUSTOM_MESSAGE,
                             repair='when-it-pays')
    [unit] = summary.coverage.units
    assert (unit.errors, unit.repair_rounds) == (0, 0), summary.diagnostics
    [node] = summary.nodes
    [publisher] = node.publishers
    # (the node subscribes to nothing: that decides first)
    assert (publisher.topic, publisher.label, publisher.pattern) == (
        'frames', 'independent', 'no_subscribers')
