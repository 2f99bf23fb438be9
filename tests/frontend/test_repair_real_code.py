# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Model mode on real code: newer rclcpp, libraries' templates, lost calls."""


from colcon_rsia.frontend.cpp.model_mode.recovery import rules
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.package import analysis
from conftest import analyze_source
from model_sources import acme_vision_package
from model_sources import analyze_acme_vision
from model_sources import line_reader
import pytest


# what real ROS 2 code uses of rclcpp beyond the basics (Iron/Jazzy)
NEWER_RCLCPP = r"""
#include <rclcpp/rclcpp.hpp>
#include <rclcpp/parameter_client.hpp>
#include <std_msgs/msg/string.hpp>

class Watcher : public rclcpp::Node
{
public:
  Watcher()
  : Node("watcher", rclcpp::NodeOptions().enable_logger_service(true))
  {
    rclcpp::PublisherOptions options;
    options.event_callbacks.matched_callback =
      [](rclcpp::MatchedInfo & info) { (void)info.current_count; };
    pub_ = create_publisher<std_msgs::msg::String>("status", 10, options);
    auto overrides =
      get_node_parameters_interface()->get_parameter_overrides();
    remote_ = std::make_shared<rclcpp::AsyncParametersClient>(this, "other");
    sync_ = std::make_shared<rclcpp::SyncParametersClient>(this, "other");
    remote_->wait_for_service(std::chrono::seconds(1));
    auto values = sync_->get_parameters({"rate"});
    get_clock()->wait_until_started(rclcpp::Duration(1, 0));
    (void)overrides; (void)values; (void)get_clock()->started();
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::AsyncParametersClient::SharedPtr remote_;
  rclcpp::SyncParametersClient::SharedPtr sync_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Watcher>());
}
"""


def test_the_model_has_what_newer_rclcpp_code_uses(tmp_path):
    summary = analyze_source(tmp_path, 'watcher', NEWER_RCLCPP)
    [unit] = summary.coverage.units
    # no repair needed: the model headers declare all of it
    assert (unit.errors, unit.repair_rounds) == (0, 0), summary.diagnostics
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['status']


# endpoints created through an object of a template parameter's type: the
# call resolves only in instantiations, which the AST does not show
TEMPLATED_HELPER = r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Relay
{
public:
  template<class NodeT>
  explicit Relay(NodeT node)
  {
    pub_ = node->template create_publisher<std_msgs::msg::String>("relayed", 10);
    sub_ = node->template create_subscription<std_msgs::msg::String>(
      "incoming", 10,
      [this](std_msgs::msg::String::ConstSharedPtr msg) { pub_->publish(*msg); });
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("relay");
  Relay relay(node);
  rclcpp::spin(node);
}
"""


def test_calls_on_a_template_parameter_are_recognised_by_name(tmp_path):
    summary = analyze_source(tmp_path, 'relay', TEMPLATED_HELPER)
    recorded = sorted((c.role, c.line, c.recorded)
                      for c in summary.coverage.call_sites)
    # both calls have facts (in the unit: the node's main reaches the
    # template constructor only through its instantiation)
    assert [(role, line) for role, line, _ in recorded] == [
        ('publisher', 11), ('subscriber', 12)]
    assert all(where != 'none' for _, _, where in recorded)


def test_call_sites_in_headers_no_unit_includes_are_not_counted(tmp_path):
    package = acme_vision_package(tmp_path)
    (package / 'include' / 'acme_vision').mkdir(parents=True)
    # a header nothing includes: the build never compiles its code
    (package / 'include' / 'acme_vision' / 'unused.hpp').write_text(
        '#include <rclcpp/rclcpp.hpp>\n'
        'inline void unused(rclcpp::Node & node)\n'
        '{\n'
        '  node.create_publisher<std_msgs::msg::String>("never", 1);\n'
        '}\n')
    summary = analyze_acme_vision(package, tmp_path / 'build' / 'acme_vision')
    by_file = {(c.file, c.role): c.recorded
               for c in summary.coverage.call_sites}
    assert by_file == {
        ('include/acme_vision/unused.hpp', 'publisher'): 'unread',
        ('src/detector_node.cpp', 'publisher'): 'node',
        ('src/detector_node.cpp', 'subscriber'): 'node'}
    from colcon_rsia.package.coverage import package_report
    report = package_report(summary)
    assert report['call_sites']['publisher']['sites'] == 1
    assert report['in_unread_files'] == [{
        'file': 'include/acme_vision/unused.hpp', 'line': 4,
        'role': 'publisher', 'api': 'create_publisher'}]


# a statement no repair makes whole: its call is read from the tokens
LOST_CALL = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>

ros::Publisher kept;

void keep(ros::NodeHandle& nh)
{
  kept = nh.advertise<std_msgs::String>("kept", 1);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "talker");
  ros::NodeHandle nh;
  keep(nh);
  // (far enough from the call the parse kept: the coverage matches calls
  // to facts a few lines apart, as a call may span lines)
  ros::Publisher pub = nh.advertise<std_msgs::String>(("chatter"), , 1);
  ros::spin();
}
"""


def test_a_unit_whose_parse_lost_a_call_says_so(tmp_path):
    summary = analyze_source(tmp_path, 'talker', LOST_CALL,
                             repair=analysis.REPAIR_WHEN_IT_PAYS)
    [unit] = summary.coverage.units
    assert unit.package_errors >= 1
    # the broken advertise (its fact read from tokens, its name through
    # the parentheses), not the other
    assert unit.lost_calls == 1
    [node] = summary.nodes
    assert sorted(p.topic for p in node.publishers) == ['chatter', 'kept']


def test_scripts_no_node_runs_are_unread_not_missed(tmp_path):
    # a C++ package's Python tool its CMake installs as no node: its call
    # sites are in code no node runs ('unread'), not facts the analysis
    # missed ('none'), and not absent from the coverage either
    from colcon_rsia.package.runner import analyze
    package = acme_vision_package(tmp_path)
    (package / 'scripts').mkdir()
    (package / 'scripts' / 'echo_tool.py').write_text(
        'import rclpy\n'
        'from std_msgs.msg import String\n'
        'node = rclpy.create_node("echo_tool")\n'
        'node.create_subscription(String, "detections", print, 1)\n')
    outcome = analyze(
        name='acme_vision', package_type='ros.ament_cmake', path=str(package),
        build_base=str(tmp_path / 'build' / 'acme_vision'), jobs=1,
        header_mode='model', workspace_package_dirs=[str(package)],
        without_build=True)
    by_file = {(c.file, c.role): c.recorded
               for c in outcome.summary.coverage.call_sites}
    assert by_file == {
        ('scripts/echo_tool.py', 'subscriber'): 'unread',
        ('src/detector_node.cpp', 'publisher'): 'node',
        ('src/detector_node.cpp', 'subscriber'): 'node'}


@pytest.mark.parametrize('line,expected', [
    # a template argument is a type, a value in an expression an enumerator
    ('std::unique_ptr<bond::Bond> bond_;', ('type', 'bond::Bond')),
    ('label->setAlignment(Qt::AlignCenter);', ('constant', 'Qt::AlignCenter')),
])
def test_camel_case_names_in_a_namespace_by_their_use(line, expected):
    namespace = expected[1].split('::')[0]
    found = rules.repairs_from_diagnostics(
        [(f"use of undeclared identifier '{namespace}'", 'a.cpp', 1,
          line.index(namespace) + 1)], line_reader(line), texts=[line])
    assert found == {('namespace', namespace), expected}


# A controller-style ROS 1 node that compiles against the real headers: a
# handle from an unknown library assigned from a call on another unknown
# object, a command handed over through realtime_tools::RealtimeBuffer, a
# vector built from a message field's iterators.
HANDLES_AND_BUFFERS = r"""
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <hardware_interface/joint_command_interface.h>
#include <realtime_tools/realtime_buffer.h>
#include <string>
#include <vector>

struct Command { double position; };

class ArmController
{
public:
  bool init(hardware_interface::EffortJointInterface* hw, ros::NodeHandle& nh)
  {
    joint_ = hw->getHandle(std::string("elbow"));
    state_pub_ = nh.advertise<sensor_msgs::Imu>("state", 1);
    command_sub_ = nh.subscribe("command", 1, &ArmController::onCommand, this);
    return true;
  }

  void update()
  {
    Command command = *(buffer_.readFromRT());
    joint_.setCommand(command.position);
  }

private:
  void onCommand(const sensor_msgs::Imu::ConstPtr& msg)
  {
    std::vector<double> covariance(msg->orientation_covariance.begin(),
                                   msg->orientation_covariance.end());
    Command command;
    command.position = covariance.empty() ? 0.0 : covariance[0];
    buffer_.writeFromNonRT(command);
    state_pub_.publish(*msg);
  }

  hardware_interface::JointHandle joint_;
  realtime_tools::RealtimeBuffer<Command> buffer_;
  ros::Publisher state_pub_;
  ros::Subscriber command_sub_;
};

int main(int argc, char** argv)
{
  ros::init(argc, argv, "arm_controller");
  ros::NodeHandle nh;
  ArmController controller;
  ros::spin();
}
"""


def test_no_model_error_on_handles_buffers_and_field_iterators(tmp_path):
    summary = analyze_source(tmp_path, 'arm', HANDLES_AND_BUFFERS)
    [unit] = summary.coverage.units
    # before: `joint_ = hw->getHandle(...)` was an ambiguous operator=
    # between the stand-in's implicit copy and move assignments, and
    # RealtimeBuffer and the iterator pair were errors of the model
    assert unit.errors == 0, summary.diagnostics
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['state']
    assert [s.topic for s in node.subscribers] == ['command']


# a library's class templates with value parameters (Eigen, Ceres): the
# repair declares them with the parameter kinds their uses show
EIGEN_AND_CERES = r"""
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>
#include <Eigen/Core>
#include <ceres/ceres.h>
#include <string>

struct Residual
{
  template <class T>
  bool operator()(const T* x, T* r) const { r[0] = x[0]; return true; }
};

ros::Publisher pub;

void onValue(const std_msgs::Float64::ConstPtr& msg)
{
  Eigen::Matrix<double, 3, 3> rotation = Eigen::Matrix<double, 3, 3>::Identity();
  auto* cost = new ceres::AutoDiffCostFunction<Residual, 1, 1>(new Residual);
  pub.publish(*msg);
}

void onCommand(const std_msgs::String::ConstPtr& msg)
{
  // a field to a number: std::string only, not also std::wstring
  int index = std::stoi(msg->data);
}

int main(int argc, char** argv)
{
  ros::init(argc, argv, "estimator");
  ros::NodeHandle nh;
  pub = nh.advertise<std_msgs::Float64>("estimate", 1);
  ros::Subscriber sub = nh.subscribe("value", 1, onValue);
  ros::Subscriber commands = nh.subscribe("command", 1, onCommand);
  ros::spin();
}
"""


def test_templates_with_value_parameters_are_repaired(tmp_path):
    summary = analyze_source(tmp_path, 'estimator', EIGEN_AND_CERES)
    [unit] = summary.coverage.units
    # before: `template <class...>` took no 3, and a member of a
    # specialisation ('Eigen::Matrix<double, 3, 3>') was not declared
    assert unit.errors == 0, summary.diagnostics
    [node] = summary.nodes
    [publisher] = node.publishers
    assert (publisher.topic, publisher.label) == ('estimate', 'dependent')


# what real ROS 2 nodes use of parameters, tf2 and pluginlib beyond the
# basics: all of it is in the model, so no repair is needed
PARAMETERS_TF2_PLUGINS = r"""
#include <memory>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/pose_stamped.hpp>
#include <pluginlib/class_loader.hpp>
#include <tf2/LinearMath/Quaternion.hpp>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.hpp>

namespace planning { class Smoother { public: virtual ~Smoother() = default; }; }

class Planner : public rclcpp::Node
{
public:
  Planner()
  : Node("planner"), loader_("planning", "planning::Smoother")
  {
    smoother_ = loader_.createSharedInstance("planning/Spline");
    pub_ = create_publisher<geometry_msgs::msg::PoseStamped>("goal", 10);
    params_ = get_node_parameters_interface();
    params_->set_parameters({rclcpp::Parameter("active", true)});
    client_ = std::make_shared<rclcpp::AsyncParametersClient>(this);
    events_ = client_->on_parameter_event(
      [this](std::shared_ptr<const rcl_interfaces::msg::ParameterEvent> event) {
        for (const auto & changed : event->changed_parameters) {
          gain_ = rclcpp::Parameter::from_parameter_msg(changed).as_double();
        }
      });
  }

  void turn(const geometry_msgs::msg::PoseStamped & pose)
  {
    tf2::Quaternion heading;
    tf2::fromMsg(pose.pose.orientation, heading);
    tf2::Quaternion quarter;
    quarter.setRPY(0.0, 0.0, tf2::getYaw(pose.pose.orientation) * gain_);
    heading *= quarter;
    geometry_msgs::msg::PoseStamped out = pose;
    out.pose.orientation = tf2::toMsg(heading);
    pub_->publish(out);
  }

private:
  pluginlib::ClassLoader<planning::Smoother> loader_;
  std::shared_ptr<planning::Smoother> smoother_;
  rclcpp::node_interfaces::NodeParametersInterface::SharedPtr params_;
  rclcpp::AsyncParametersClient::SharedPtr client_;
  rclcpp::Subscription<rcl_interfaces::msg::ParameterEvent>::SharedPtr events_;
  rclcpp::Publisher<geometry_msgs::msg::PoseStamped>::SharedPtr pub_;
  double gain_ = 1.0;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Planner>());
}
"""


def test_the_model_has_parameters_tf2_conversions_and_class_loaders(tmp_path):
    summary = analyze_source(tmp_path, 'planner', PARAMETERS_TF2_PLUGINS)
    [unit] = summary.coverage.units
    assert (unit.errors, unit.repair_rounds) == (0, 0), summary.diagnostics
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['goal']


# a class of an unknown library brought in by a using-declaration, and a
# nested pointer type of a class template (PCL's PointCloud<P>::Ptr)
USING_AND_NESTED_TYPES = r"""
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <acme_vehicle/vehicle_info_utils.hpp>

namespace braking
{
using acme::vehicle::VehicleInfo;

class Braking : public rclcpp::Node
{
public:
  Braking() : Node("braking")
  {
    sub_ = create_subscription<sensor_msgs::msg::PointCloud2>(
      "points", 1, [this](sensor_msgs::msg::PointCloud2::ConstSharedPtr msg) {
        pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
        pub_->publish(*msg);
      });
    pub_ = create_publisher<sensor_msgs::msg::PointCloud2>("obstacles", 1);
  }

private:
  VehicleInfo vehicle_info_;
  rclcpp::Subscription<sensor_msgs::msg::PointCloud2>::SharedPtr sub_;
  rclcpp::Publisher<sensor_msgs::msg::PointCloud2>::SharedPtr pub_;
};
}  // namespace braking

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<braking::Braking>());
}
"""


def test_using_declared_classes_and_nested_types_are_repaired(tmp_path):
    summary = analyze_source(tmp_path, 'braking', USING_AND_NESTED_TYPES)
    [unit] = summary.coverage.units
    # before: a global VehicleInfo beside vehicle_info_utils::VehicleInfo
    # ('must use struct tag'), and Ptr declared as a value
    assert unit.errors == 0, summary.diagnostics
    [node] = summary.nodes
    [publisher] = node.publishers
    assert (publisher.topic, publisher.label) == ('obstacles', 'dependent')


def test_a_global_function_gives_way_to_the_qualified_one(tmp_path):
    # `f(x)` failed before `using ns::f;` took effect (a global f), then
    # the using-declaration (ns::f): both would conflict at the using
    header = tmp_path / 'unit.h'
    store.add_repairs(str(header), 'unit.cpp', {
        ('function', 'calcOffsetPose')})
    store.add_repairs(str(header), 'unit.cpp', {
        ('namespace', 'motion_utils'),
        ('function', 'motion_utils::calcOffsetPose')})
    assert store.read_repairs(str(header)) == {
        ('namespace', 'motion_utils'),
        ('function', 'motion_utils::calcOffsetPose')}
    # a class's function beside it (Qt's connect(...) in a derived class
    # and QObject::connect(...)) leaves the global one
    store.add_repairs(str(header), 'unit.cpp', {
        ('function', 'connect'), ('function', 'QObject::connect')})
    assert {('function', 'connect'), ('function', 'QObject::connect')} <= \
        store.read_repairs(str(header))


def test_a_global_class_gives_way_to_the_qualified_one(tmp_path):
    # round 1 saw `VehicleInfo v;` before acme::vehicle existed (a global
    # class), round 2 the class itself: under `using namespace acme::vehicle`
    # both would be found and every use ambiguous
    header = tmp_path / 'unit.h'
    store.add_repairs(str(header), 'unit.cpp', {('type', 'VehicleInfo')})
    store.add_repairs(str(header), 'unit.cpp', {
        ('namespace', 'acme::vehicle'), ('type', 'acme::vehicle::VehicleInfo')})
    assert store.read_repairs(str(header)) == {
        ('namespace', 'acme::vehicle'), ('type', 'acme::vehicle::VehicleInfo')}


# the field typedefs of ROS 2 message classes
FIELD_TYPES = r"""
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <rclcpp/rclcpp.hpp>
#include <diagnostic_msgs/msg/diagnostic_array.hpp>
#include <diagnostic_msgs/msg/diagnostic_status.hpp>

using diagnostic_msgs::msg::DiagnosticArray;
using diagnostic_msgs::msg::DiagnosticStatus;
using DiagnosticLevel = DiagnosticStatus::_level_type;
using ArrayLevel = DiagnosticArray::_status_type::value_type::_level_type;

// a QoS value whose name ends like an export macro (..._LOCAL)
struct Spec
{
  static constexpr auto durability = RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL;
};

class Monitor : public rclcpp::Node
{
public:
  Monitor() : Node("monitor")
  {
    pub_ = create_publisher<DiagnosticStatus>("worst", 1);
    sub_ = create_subscription<DiagnosticArray>(
      "diagnostics", 1, [this](DiagnosticArray::ConstSharedPtr msg) {
        DiagnosticLevel worst = DiagnosticStatus::OK;
        for (const auto & status : msg->status) {
          ArrayLevel level = status.level;
          if (level > worst) {
            worst = level;
          }
        }
        names_[worst] = "worst";
        counts_[worst] += 1;
        DiagnosticStatus out;
        out.level = worst;
        pub_->publish(out);
      });
  }

private:
  std::map<DiagnosticLevel, std::string> names_;
  std::unordered_map<DiagnosticLevel, int> counts_;
  rclcpp::Publisher<DiagnosticStatus>::SharedPtr pub_;
  rclcpp::Subscription<DiagnosticArray>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""


def test_message_field_types_are_declared(tmp_path):
    summary = analyze_source(tmp_path, 'monitor', FIELD_TYPES)
    [unit] = summary.coverage.units
    # before: "no type named '_level_type' in DiagnosticStatus_<...>"
    assert (unit.errors, unit.repair_rounds) == (0, 0), summary.diagnostics
    [node] = summary.nodes
    [publisher] = node.publishers
    assert (publisher.topic, publisher.label) == ('worst', 'dependent')


def test_the_packages_own_endpoint_functions_are_no_ros_call_sites():
    from colcon_rsia.package.call_sites import cxx_call_sites
    from colcon_rsia.package.call_sites import cxx_own_functions
    code = '\n'.join([
        'void ns::Filter::subscribe()',                          # 1
        '{',
        '  subscribe(name_);',                                    # 3
        '}',
        'void ns::Filter::subscribe(const std::string & name)',  # 5
        '{',
        '  sub_ = create_subscription<Cloud>(name, 1, cb);',      # 7
        '  this->subscribe();',                                   # 8
        '  other_.subscribe(node_);',                             # 9
        '}',
        'std::shared_ptr<P> W::create_publisher(const std::string & t)',
        '{ return node_->create_publisher<M>(t, 1); }',           # 12
        'auto p = rclcpp::create_publisher<M>(node, "x", 1);',    # 13
    ])
    own = cxx_own_functions(code)
    assert own == {'subscribe', 'create_publisher'}
    # definitions and the package's own calls of them are not counted; an
    # object's method may be ROS's (counted: the yardstick errs that way)
    assert [line for line, _, _ in cxx_call_sites(code, own)] == [
        7, 9, 12, 13]


def test_a_member_used_with_template_arguments_is_a_member_template(
        tmp_path):
    header = tmp_path / 'unit.h'
    store.ensure_repair_header(str(header), 'src/unit.cpp')
    line = line_reader('auto r = lanelet.regulatoryElementsAs<Light>();')
    # first use: declared as a member of the unknown class (a value)
    first = rules.repairs_from_diagnostics(
        [("unknown type name 'Lanelet'", 'a.cpp', 1, 1),
         ("no member named 'size' in 'lanelet::Lanelet'", 'a.cpp', 1, 1)],
        line)
    assert store.add_repairs(str(header), 'src/unit.cpp', first | {
        ('type', 'lanelet::Lanelet')})
    # clang then says it is no template: it becomes a member template
    second = rules.repairs_from_diagnostics(
        [("'size' does not name a template but is followed by template "
          'arguments', 'a.cpp', 1, 18)], line)
    assert second == {('template-use', 'size')}
    assert store.add_repairs(str(header), 'src/unit.cpp', second)
    assert ('member-template', 'lanelet::Lanelet::size') in \
        store.read_repairs(str(header))
    # written as a template in a first go when the use shows it
    assert rules.repairs_from_diagnostics(
        [("no member named 'regulatoryElementsAs' in 'lanelet::Lanelet'",
          'a.cpp', 1, 19)], line) == {
        ('member-template', 'lanelet::Lanelet::regulatoryElementsAs')}


UNKNOWN_LIBRARY_TEMPLATES = """
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <acme_map/map.hpp>

class MapRelay : public rclcpp::Node
{
public:
  MapRelay() : Node("map_relay")
  {
    pub_ = create_publisher<std_msgs::msg::String>("lights", 1);
    auto lane = map_->laneletLayer.get(3);
    for (const auto & light : lane.regulatoryElementsAs<acme_map::Light>()) {
      std_msgs::msg::String text;
      pub_->publish(text);
    }
    auto index = map_->template index<acme_map::Light>();
  }

private:
  std::shared_ptr<acme_map::Map> map_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<MapRelay>());
  return 0;
}
"""


def test_members_of_unknown_values_called_with_template_arguments(tmp_path):
    # `lane` holds what an unknown library returns; its members are
    # only ever called with template arguments: member templates, and
    # what it returns can be iterated
    summary = analyze_source(tmp_path, 'relay', UNKNOWN_LIBRARY_TEMPLATES)
    assert not [d for d in summary.diagnostics if 'parse error' in d], \
        summary.diagnostics
    [node] = summary.nodes
