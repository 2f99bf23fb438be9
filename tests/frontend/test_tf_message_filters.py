# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""tf's message filters: a subscription's messages, passed on once they transform.

`tf::MessageFilter` (ROS 1) and `tf2_ros::MessageFilter` (both) take their
input filter first, then the tf object and the target frame; their
callback runs for the input's messages. The tf object is no input: its
/tf subscriptions only release queued messages. Expectations written by
hand from the code below.
"""

from conftest import analyze_source
import pytest

# ROS 1: amcl's form, a filter made with `new` from a message_filters
# subscriber, the callback given by boost::bind
LOCALIZER = r"""
#include <ros/ros.h>
#include <tf/transform_listener.h>
#include <tf/message_filter.h>
#include <message_filters/subscriber.h>
#include <sensor_msgs/LaserScan.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <boost/bind.hpp>

class Localizer
{
public:
  Localizer() : private_nh_("~")
  {
    pose_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 2, true);
    laser_scan_sub_ = new message_filters::Subscriber<sensor_msgs::LaserScan>(nh_, "scan", 100);
    laser_scan_filter_ = new tf::MessageFilter<sensor_msgs::LaserScan>(
      *laser_scan_sub_, tf_, "odom", 100);
    laser_scan_filter_->registerCallback(boost::bind(&Localizer::laserReceived, this, _1));
  }

private:
  void laserReceived(const sensor_msgs::LaserScanConstPtr & scan)
  {
    geometry_msgs::PoseWithCovarianceStamped p;
    p.header = scan->header;
    pose_pub_.publish(p);
  }
  ros::NodeHandle nh_, private_nh_;
  tf::TransformListener tf_;
  ros::Publisher pose_pub_;
  message_filters::Subscriber<sensor_msgs::LaserScan> * laser_scan_sub_;
  tf::MessageFilter<sensor_msgs::LaserScan> * laser_scan_filter_;
};

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "amcl");
  Localizer l;
  ros::spin();
}
"""

# ROS 2: a subscriber member, the filter made with make_shared
PROJECTOR = r"""
#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "message_filters/subscriber.h"
#include "tf2_ros/buffer.h"
#include "tf2_ros/message_filter.h"
#include "tf2_ros/transform_listener.h"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "sensor_msgs/msg/point_cloud2.hpp"

class Projector : public rclcpp::Node
{
public:
  Projector() : Node("projector")
  {
    buffer_ = std::make_shared<tf2_ros::Buffer>(get_clock());
    listener_ = std::make_shared<tf2_ros::TransformListener>(*buffer_);
    cloud_pub_ = create_publisher<sensor_msgs::msg::PointCloud2>("cloud", 10);
    scan_sub_.subscribe(this, "scan", rclcpp::SensorDataQoS().get_rmw_qos_profile());
    filter_ = std::make_shared<tf2_ros::MessageFilter<sensor_msgs::msg::LaserScan>>(
      scan_sub_, *buffer_, "base_link", 10, get_node_logging_interface(),
      get_node_clock_interface());
    filter_->registerCallback(&Projector::onScan, this);
  }

private:
  void onScan(const sensor_msgs::msg::LaserScan::ConstSharedPtr & scan)
  {
    sensor_msgs::msg::PointCloud2 cloud;
    cloud.header = scan->header;
    cloud_pub_->publish(cloud);
  }
  std::shared_ptr<tf2_ros::Buffer> buffer_;
  std::shared_ptr<tf2_ros::TransformListener> listener_;
  message_filters::Subscriber<sensor_msgs::msg::LaserScan> scan_sub_;
  std::shared_ptr<tf2_ros::MessageFilter<sensor_msgs::msg::LaserScan>> filter_;
  rclcpp::Publisher<sensor_msgs::msg::PointCloud2>::SharedPtr cloud_pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Projector>());
}
"""


# the other form: no input at construction, connected later
CONNECTED = LOCALIZER.replace(
    'laser_scan_filter_ = new tf::MessageFilter<sensor_msgs::LaserScan>(\n'
    '      *laser_scan_sub_, tf_, "odom", 100);',
    'laser_scan_filter_ = new tf::MessageFilter<sensor_msgs::LaserScan>(\n'
    '      tf_, "odom", 100);\n'
    '    laser_scan_filter_->connectInput(*laser_scan_sub_);')


def test_the_connected_form_replaced_the_constructed_one():
    # (a replacement that matched nothing would test LOCALIZER twice)
    assert 'connectInput' in CONNECTED and 'connectInput' not in LOCALIZER


@pytest.mark.parametrize('source, package, topic, callback', [
    (CONNECTED, 'localizer', 'amcl_pose', 'Localizer::laserReceived'),
    (LOCALIZER, 'localizer', 'amcl_pose', 'Localizer::laserReceived'),
    (PROJECTOR, 'projector', 'cloud', 'Projector::onScan'),
])
def test_a_tf_filter_passes_its_inputs_messages(
        tmp_path, source, package, topic, callback):
    summary = analyze_source(tmp_path, package, source,
                             repair='when-it-pays')
    [node] = summary.nodes
    callbacks = {s.topic: s.callback for s in node.subscribers}
    # before: no subscription had a callback, the publisher's trigger was
    # any input ('*')
    assert callbacks == {'scan': callback, '/tf': None, '/tf_static': None}
    [publisher] = node.publishers
    assert publisher.topic == topic
    assert publisher.label == 'dependent'
    assert [t.name for t in publisher.triggers] == ['scan']
