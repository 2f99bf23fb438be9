# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""APIs of a library that is neither installed nor modelled.

The model mode's repairs declare such a library's classes from clang's
errors; a call the API table names is still read by the name the code
wrote. Expectations written by hand from the code below.
"""

from colcon_rsia.frontend.cpp.model_mode.source_names import \
    override_defines
from conftest import analyze_source
from model_sources import assert_analyzes_clean

POLLING = r"""
#include <chrono>
#include <memory>

#include <autoware_utils/ros/polling_subscriber.hpp>
#include <nav_msgs/msg/odometry.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Poller : public rclcpp::Node
{
public:
  Poller()
  : Node("poller")
  {
    kinematics_ = autoware_utils::InterProcessPollingSubscriber<
      nav_msgs::msg::Odometry>::create_subscription(
      this, "~/input/kinematics", 1);
    pub_ = create_publisher<std_msgs::msg::String>("out", 1);
    timer_ = create_wall_timer(std::chrono::milliseconds(100), [this]() {
        auto kinematics = kinematics_->take_data();
        auto odometry = odometry_.take_data();
        pub_->publish(std_msgs::msg::String());
      });
  }

private:
  autoware_utils::InterProcessPollingSubscriber<nav_msgs::msg::Odometry>::
  SharedPtr kinematics_;
  // a default member initializer: run by the constructor
  autoware_utils::InterProcessPollingSubscriber<nav_msgs::msg::Odometry>
  odometry_{this, "~/input/odometry"};
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Poller>());
}
"""


def test_polling_subscribers_of_an_unmodelled_library_are_inputs(tmp_path):
    summary = analyze_source(tmp_path, 'poller', POLLING)
    [node] = summary.nodes
    # both forms: the static create_subscription and the constructor of
    # a member; a polling subscription calls nothing
    assert sorted((s.topic, s.msg_type, s.api, s.callback)
                  for s in node.subscribers) == [
        ('~/input/kinematics', 'nav_msgs::msg::Odometry',
         'autoware_utils::InterProcessPollingSubscriber', None),
        ('~/input/odometry', 'nav_msgs::msg::Odometry',
         'autoware_utils::InterProcessPollingSubscriber', None),
    ]
    # the data are taken in the 100 ms timer: its rate, not the inputs'
    [out] = node.publishers
    assert (out.topic, out.label, out.pattern, out.rate_hz) == \
        ('out', 'independent', 'timer', 10.0)


def test_a_static_create_subscription_beside_the_nodes_own(tmp_path):
    # the package also calls a node's `create_subscription<M>(...)`: every
    # catch-all then has a member template of that name, which a static
    # call reaches through the unknown class template, and through the
    # class a member's pointer type names (`decltype(odom_)::element_type`)
    source = POLLING.replace(
        '    pub_ = create_publisher',
        '    sub_ = this->create_subscription<std_msgs::msg::String>(\n'
        '      "in", 1, [](std_msgs::msg::String::SharedPtr) {});\n'
        '    odom_ = decltype(odom_)::element_type::create_subscription(\n'
        '      this, "~/input/odom", 1);\n'
        '    pub_ = create_publisher').replace(
        '  rclcpp::TimerBase::SharedPtr timer_;',
        '  rclcpp::TimerBase::SharedPtr timer_;\n'
        '  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;\n'
        '  autoware_utils::InterProcessPollingSubscriber<\n'
        '    nav_msgs::msg::Odometry>::SharedPtr odom_;')
    summary = analyze_source(tmp_path, 'poller', source)
    assert [u.package_errors for u in summary.coverage.units] == [0], \
        summary.diagnostics
    [node] = summary.nodes
    assert sorted((s.topic, s.api) for s in node.subscribers) == [
        ('in', 'rclcpp::Node::create_subscription'),
        ('~/input/kinematics', 'autoware_utils::InterProcessPollingSubscriber'),
        ('~/input/odom', 'autoware_utils::InterProcessPollingSubscriber'),
        ('~/input/odometry', 'autoware_utils::InterProcessPollingSubscriber'),
    ]


# the package that implements an API: its own declaration is the API's
OWN_API = r"""
#include <ros/ros.h>
namespace image_transport
{
class Publisher {};
class ImageTransport
{
public:
  explicit ImageTransport(const ros::NodeHandle & nh);
  Publisher advertise(const std::string & base_topic, uint32_t queue_size);
};
}  // namespace image_transport

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "republish");
  ros::NodeHandle nh;
  image_transport::ImageTransport it(nh);
  image_transport::Publisher pub = it.advertise("out", 1);
  ros::spin();
}
"""


def test_an_api_declared_by_the_package_that_implements_it(tmp_path):
    summary = analyze_source(tmp_path, 'image_transport', OWN_API)
    [node] = summary.nodes
    assert [(p.topic, p.api, p.msg_type) for p in node.publishers] == [
        ('out', 'image_transport::ImageTransport::advertise',
         'sensor_msgs::Image')]


# image_transport's republish: an output transport loaded as a plugin, its
# publisher made through the plugin interface (no model of it: the repairs
# declare image_transport::PublisherPlugin, whose advertise is then a
# member every catch-all has, called like a functor)
REPUBLISH = r"""
#include <ros/ros.h>
#include <image_transport/image_transport.h>
#include <image_transport/publisher_plugin.h>
#include <pluginlib/class_loader.h>

int main(int argc, char** argv)
{
  ros::init(argc, argv, "image_republisher");
  ros::NodeHandle nh;
  image_transport::ImageTransport it(nh);
  typedef image_transport::PublisherPlugin Plugin;
  pluginlib::ClassLoader<Plugin> loader("image_transport",
                                        "image_transport::PublisherPlugin");
  boost::shared_ptr<Plugin> pub(loader.createInstance("raw_pub"));
  pub->advertise(nh, "out", 1, image_transport::SubscriberStatusCallback(),
                 image_transport::SubscriberStatusCallback(), ros::VoidPtr(),
                 false);
  image_transport::Subscriber sub = it.subscribe("in", 1, &callback);
  ros::spin();
}
"""


def test_a_plugin_interface_call_is_named_by_the_objects_class(tmp_path):
    summary = analyze_source(tmp_path, 'republish', REPUBLISH)
    [node] = summary.nodes
    # the topic is the call's second argument (its first is the handle);
    # before, the functor's object `pub->advertise` was taken for the
    # first argument and the call for NodeHandle::advertise by its name
    assert [(p.topic, p.api, p.msg_type) for p in node.publishers] == [
        ('out', 'image_transport::PublisherPlugin::advertise',
         'sensor_msgs::Image')]
    assert [s.topic for s in node.subscribers] == ['in']


# a library whose include directory is capitalised, like its namespace;
# every name the code uses of it comes from the missing headers
CAPITALISED_LIBRARY = r"""
#include <Eigen/Core>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>

class Norm : public rclcpp::Node
{
public:
  Norm() : Node("norm")
  {
    pub_ = create_publisher<std_msgs::msg::Float64>("norm", 1);
  }

private:
  double norm(const Eigen::VectorXd & v, const Eigen::MatrixXd & weights) const
  {
    return (weights * v).norm();
  }
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};
"""


def test_a_capitalised_library_directory_is_its_namespace(tmp_path):
    # before: "use of undeclared identifier 'Eigen'", left unrepaired
    # since no call was lost
    assert_analyzes_clean(tmp_path, 'norm', CAPITALISED_LIBRARY)


# include directories mirror namespaces below the top one: here the top
# namespace is the package's own (`corp`) or a model library's (`boost`),
# and the missing headers declare `corp::planning_utils` and
# `boost::geometry`; never a class the model declares (`boost::thread`)
NESTED_NAMESPACES = r"""
#include <boost/geometry/algorithms/intersects.hpp>
#include <boost/thread/thread.hpp>
#include <boost/thread/xtime.hpp>
#include <corp/planning_utils/path.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/bool.hpp>

namespace corp::planner
{
class Checker : public rclcpp::Node
{
public:
  Checker() : Node("checker")
  {
    pub_ = create_publisher<std_msgs::msg::Bool>("crossing", 1);
  }

private:
  bool crossing(const corp::planning_utils::Path & a, const corp::planning_utils::Path & b)
  {
    auto smoothed = planning_utils::smooth(a);
    unsigned cores = boost::thread::hardware_concurrency();
    return cores && boost::geometry::intersects(smoothed, b);
  }
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr pub_;
};
}  // namespace corp::planner
"""


def test_nested_namespaces_of_unknown_include_directories(tmp_path):
    # before: "no member named 'planning_utils' in namespace 'corp'" and
    # "no member named 'geometry' in namespace 'boost'"
    assert_analyzes_clean(tmp_path, 'checker', NESTED_NAMESPACES)


# a plugin of a simulator the model does not know: its base class is a
# catch-all, with no virtual member for `override` to match
UNKNOWN_BASE_OVERRIDES = r"""
#include <memory>
#include <sim/plugin.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>

namespace sim_plugins
{
class Thermometer : public sim::SensorPlugin
{
public:
  void Load(sim::SensorPtr sensor, sim::ElementPtr sdf) override
  {
    node_ = std::make_shared<rclcpp::Node>("thermometer");
    pub_ = node_->create_publisher<std_msgs::msg::Float64>("temperature", 1);
  }
  void OnUpdate() override
  {
    pub_->publish(std_msgs::msg::Float64());
  }

private:
  rclcpp::Node::SharedPtr node_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};
}  // namespace sim_plugins
"""


def test_override_of_an_unknown_base_class_is_no_error(tmp_path):
    # before: "only virtual member functions can be marked 'override'",
    # twice, left unrepaired since no call was lost
    assert_analyzes_clean(tmp_path, 'thermometer', UNKNOWN_BASE_OVERRIDES)


def test_override_is_kept_where_the_sources_name_a_variable_so():
    keyword = 'void Load() override;\nint Size() const noexcept override;'
    assert override_defines([keyword]) == ['-Doverride=']
    assert override_defines([keyword, 'bool override = false;']) == []
    # a trailing return type: not told apart from a name, so kept
    assert override_defines(['auto f() -> int override;']) == []


# directories that add to their namespace's name: a driver's SDK, a
# versioned library, a stack's package named `<stack>_<package>`
PREFIX_NAMESPACES = r"""
#include <servo_sdk/servo_sdk.h>
#include <mapkit2_core/primitives/Lanelet.h>
#include <corp_planning_utils/path.hpp>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>

namespace corp::driver
{
class Servo : public rclcpp::Node
{
public:
  Servo() : Node("servo")
  {
    pub_ = create_publisher<std_msgs::msg::Float64>("angle", 1);
    port_ = servo::PortHandler::getPortHandler("/dev/ttyUSB0");
  }

private:
  double length(const mapkit::Lanelet & lane, const corp::planning_utils::Path & path)
  {
    return planning_utils::length(path) + lane.length();
  }
  servo::PortHandler * port_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
};
}  // namespace corp::driver
"""


def test_namespaces_a_directory_name_adds_to(tmp_path):
    # before: "use of undeclared identifier 'servo'", 'mapkit', and "no
    # member named 'planning_utils' in namespace 'corp'"
    assert_analyzes_clean(tmp_path, 'servo', PREFIX_NAMESPACES)


# namespaces that only an unmodelled library's header brings: the unit
# never includes Eigen's or yaml-cpp's own headers
BROUGHT_NAMESPACES = r"""
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
#include <corp_lidar/filter.hpp>

namespace ec = Eigen;

class Tilt : public rclcpp::Node
{
public:
  Tilt() : Node("tilt")
  {
    YAML::Node config = YAML::LoadFile("tilt.yaml");
    pub_ = create_publisher<std_msgs::msg::Float64>("tilt", 1);
    timer_ = create_wall_timer(std::chrono::milliseconds(100), [this]() {
      Eigen::AngleAxisf roll(0.1f, Eigen::Vector3f::UnitX());
      ec::Matrix3f rotation = roll.toRotationMatrix();
      std_msgs::msg::Float64 tilt;
      tilt.data = rotation(2, 2);
      pub_->publish(tilt);
    });
  }

private:
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Tilt>());
}
"""


def test_a_namespace_an_unmodelled_header_brings_is_declared(tmp_path):
    # before: "use of undeclared identifier 'Eigen'" (and 'YAML'): no
    # include of the unit named them
    summary = assert_analyzes_clean(tmp_path, 'tilt', BROUGHT_NAMESPACES)
    [node] = summary.nodes
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('tilt', 'independent')]


# a library's header named after its class, in a directory that adds to
# its namespace's name: no message, though it looks like one
CLASS_HEADER = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <lanelet2_core/LaneletMap.h>

ros::Publisher pub;

void onMap(const std_msgs::String::ConstPtr & msg)
{
  lanelet::LaneletMapPtr map(new lanelet::LaneletMap);
  for (const auto & area : map->polygonLayer) {
    std_msgs::String type;
    type.data = area.attributeOr(lanelet::AttributeName::Type, "none");
    pub.publish(type);
  }
}

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "areas");
  ros::NodeHandle nh;
  pub = nh.advertise<std_msgs::String>("area_types", 1);
  ros::Subscriber sub = nh.subscribe("map", 1, onMap);
  ros::spin();
}
"""


def test_a_header_named_after_its_class_is_no_message(tmp_path):
    # before: a message `lanelet2_core::LaneletMap`, and no `lanelet::`
    # namespace: "no member named 'LaneletMapPtr' in namespace 'lanelet'"
    summary = assert_analyzes_clean(tmp_path, 'areas', CLASS_HEADER)
    [node] = summary.nodes
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('area_types', 'dependent')]


# class templates of an unknown library with value parameters
VALUE_PARAMETERS = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
#include <Eigen/Core>
#include <spatial/rtree.hpp>

using Tree = spatial::rtree<int, spatial::rstar<16>>;
using Wide = spatial::rtree<int, spatial::rstar<16, 4>>;

class Norm : public rclcpp::Node
{
public:
  Norm() : Node("norm")
  {
    pub_ = create_publisher<std_msgs::msg::Float64>("norm", 1);
    timer_ = create_wall_timer(std::chrono::seconds(1), [this]() {
      Eigen::Matrix<double, 6, 1> twist;
      Eigen::Matrix<double, 6, 6> covariance;
      std_msgs::msg::Float64 norm;
      norm.data = (covariance * twist).norm();
      pub_->publish(norm);
    });
  }

private:
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
  rclcpp::TimerBase::SharedPtr timer_;
  Tree tree_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Norm>());
}
"""


def test_class_templates_of_values_are_declared_with_their_shape(tmp_path):
    # before: "no template named 'Matrix' in namespace 'Eigen'" and
    # "template argument for template type parameter must be a type"
    summary = assert_analyzes_clean(tmp_path, 'norm', VALUE_PARAMETERS)
    [node] = summary.nodes
    assert [(p.topic, p.label) for p in node.publishers] == [
        ('norm', 'independent')]


# names written from the global namespace (`::lib::...`)
GLOBALLY_QUALIFIED = r"""
#include <ros/ros.h>
#include <std_msgs/Int32.h>
#include <slam_core/map_builder.h>

ros::Publisher pub;

void onScan(const std_msgs::Int32::ConstPtr & msg)
{
  ::slam_core::sensor::RangeData range_data;
  auto builder = ::slam_core::mapping::CreateMapBuilder(range_data);
  std_msgs::Int32 count;
  count.data = builder.size();
  pub.publish(count);
}

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "slam");
  ros::NodeHandle nh;
  pub = nh.advertise<std_msgs::Int32>("count", 1);
  ros::Subscriber sub = nh.subscribe("scan", 1, onScan);
  ros::spin();
}
"""


def test_names_qualified_from_the_global_namespace_are_declared(tmp_path):
    # before: "no type named 'RangeData' in namespace 'slam_core::sensor'"
    summary = assert_analyzes_clean(tmp_path, 'slam', GLOBALLY_QUALIFIED)
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['count']


# a dynamic_reconfigure config named inside its package's namespace
CONFIG_IN_OWN_NAMESPACE = r"""
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <dynamic_reconfigure/server.h>
#include <scan_tools/ScanToolsConfig.h>

namespace scan_tools
{
class Scaler
{
public:
  explicit Scaler(ros::NodeHandle & nh) : srv_(nh)
  {
    pub_ = nh.advertise<std_msgs::Float64>("scale", 1);
    srv_.setCallback([this](ScanToolsConfig & config, uint32_t level) {
      reconfig(config, level);
    });
  }

private:
  void reconfig(ScanToolsConfig & config, uint32_t level)
  {
    std_msgs::Float64 scale;
    scale.data = config.scale;
    pub_.publish(scale);
  }

  ros::Publisher pub_;
  dynamic_reconfigure::Server<ScanToolsConfig> srv_;
};
}  // namespace scan_tools
"""


def test_a_config_named_in_its_packages_namespace_is_one(tmp_path):
    # the package's namespace is opened, never named: still its config
    # (before: an empty stand-in, "unknown type name 'ScanToolsConfig'")
    assert_analyzes_clean(tmp_path, 'scan_tools', CONFIG_IN_OWN_NAMESPACE)


def test_an_include_directory_of_any_characters_gets_a_stand_in():
    # (its name goes into patterns, and must not be read as one: before,
    # re.error ended the unit's preparation)
    from colcon_rsia.frontend.cpp.model_mode.stand_ins import stand_ins_for
    for include in ('c++/Widget.h', 'vendor(2/Widget.h'):
        stubs = stand_ins_for(include, ['int widgets;'])
        assert 'kind=empty' in stubs[include].split('\n', 1)[0]
