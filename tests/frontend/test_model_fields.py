# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Real code's idioms parse in model mode: message fields, casts, constants."""


from colcon_rsia.frontend.cpp.model_mode import source_names
from model_sources import assert_parses_clean


def test_a_panel_formats_what_its_node_receives_with_qstring(tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <string>
#include <QObject>

QString shown(const std::string & name, double seconds, int count)
{
  QString text = QString::fromStdString(name) + " ";
  text += QString::number(seconds, 'f', 3).rightRef(4);
  text += QString("%1 of %2").arg(count).arg(QString::number(count, 16));
  return text.isEmpty() ? QString::fromUtf8("-") : text.left(text.size() - 1);
}
""")


def test_rates_policies_iterators_and_pointer_casts_of_catch_all_values(
        tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <iterator>
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
#include <map_like/primitives.hpp>

double run(rclcpp::Node & node, const std_msgs::msg::Float64 & rate,
           const map_like::Lanelet & lanelet)
{
  // a field is a rate in hertz, not a duration message
  const auto period = rclcpp::Rate(rate.data).period();
  rclcpp::WallRate wall(rate.data);
  const auto qos = rclcpp::QoS(1).durability(rclcpp::DurabilityPolicy::TransientLocal)
                     .reliability(rclcpp::ReliabilityPolicy::Reliable);
  const auto step = rclcpp::Duration::from_nanoseconds(
    static_cast<rcl_duration_value_t>(rate.data * 1e9));
  const auto vertices = lanelet.polygon();
  auto next = std::next(vertices.cbegin());
  const auto element = std::dynamic_pointer_cast<const map_like::Crosswalk>(
    lanelet.regulatoryElements().front());
  return period.count() + step.seconds() + (next != vertices.cend()) + (element != nullptr);
}
""")


def test_a_known_member_whose_result_has_members_stays_a_catch_all():
    # OpenCV's `image.size().width`: no number
    values = source_names.used_names(
        ['int w = image.size().width + path.c_str()[0]; n = v.rows();'])[5]
    assert 'size' in values
    assert not {'c_str', 'rows'} & values
    # also through a variable (`auto size = image.size();`); a count
    # used as a number is no such use
    values = source_names.used_names([
        'auto image_size = images[i].size(); decode(image_size);\n'
        'int w = image_size.width;\n'
        'auto n = path.c_str(); auto rows = m.rows(); f(n, rows + 1);'])[5]
    assert 'size' in values
    assert not {'c_str', 'rows'} & values


def test_a_trailing_return_type_is_no_member(tmp_path):
    # a member named `QBrush` in every catch-all would hide the class
    # (`-> QBrush {` of a lambda); a call's result stays a member access
    members, *_, templates, _ = source_names.used_names([
        'auto row = [&]() -> QBrush { return {}; };\n'
        'auto Box::pose() const -> std::vector<Pose> & { return p; }\n'
        'pub = node()->create_publisher<T>("a"); if (a()->ok) {}'])
    assert members == {'ok'} and templates == {'create_publisher'}
    assert_parses_clean(tmp_path, r"""
#include <QBrush>
#include <QTableWidgetItem>
void paint(QTableWidgetItem * item, bool stale)
{
  const auto background = [&]() -> QBrush {
    if (stale) {
      return QBrush(Qt::red);
    }
    return {};
  }();
  item->setBackground(background);
}
""", repairs=[('type', 'QTableWidgetItem'), ('type', 'QBrush'),
              ('namespace', 'Qt'), ('object', 'Qt::red')])


def test_a_switch_takes_a_value_of_a_nested_unknown_type(tmp_path):
    # TensorRT's logger: `Severity` is a nested type of an unknown class
    assert_parses_clean(tmp_path, r"""
#include <trt_like/logger.hpp>

int level(trt_like::ILogger::Severity severity)
{
  switch (severity) {
    case trt_like::ILogger::Severity::kERROR:
      return 2;
    case trt_like::ILogger::Severity::kINFO:
      return 1;
    default:
      return severity ? 0 : -1;
  }
}
""", {
        ('type', 'trt_like::ILogger'),
        ('member-type', 'trt_like::ILogger::Severity')})


def test_a_catch_all_value_becomes_a_pair(tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <utility>
#include <vector>
#include <opt_like/minima.hpp>

float run(const std::vector<double> & xs)
{
  // a pair from a function of an unknown library
  const std::pair<float, float> best = opt_like::minimize(xs, 0.0, 1.0);
  return best.first;
}
""")


def test_profiles_clock_waits_enum_results_and_constexpr_field_checks(
        tmp_path):
    # forms of ros2_control's controller manager
    assert_parses_clean(tmp_path, r"""
#include <rclcpp/rclcpp.hpp>
#include <lifecycle_msgs/msg/state.hpp>
#include <handler_like/async_handler.hpp>

namespace pkg
{
enum class return_type : std::uint8_t { OK = 0, ERROR = 1 };

// every field of an rmw profile, as an aggregate
static const rmw_qos_profile_t qos_services = {
  RMW_QOS_POLICY_HISTORY_KEEP_ALL,
  1,
  RMW_QOS_POLICY_RELIABILITY_RELIABLE,
  RMW_QOS_POLICY_DURABILITY_VOLATILE,
  RMW_QOS_DEADLINE_DEFAULT,
  RMW_QOS_LIFESPAN_DEFAULT,
  RMW_QOS_POLICY_LIVELINESS_SYSTEM_DEFAULT,
  RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT,
  false};

// a constexpr function comparing a message's field type
constexpr bool needs_no_action(const lifecycle_msgs::msg::State::_id_type state)
{
  return state == lifecycle_msgs::msg::State::PRIMARY_STATE_UNKNOWN ||
         state == lifecycle_msgs::msg::State::PRIMARY_STATE_FINALIZED;
}

return_type update(rclcpp::Node & node, handler_like::AsyncHandler & handler,
                   std::unique_ptr<rclcpp::PreShutdownCallbackHandle> & handle)
{
  node.get_node_base_interface()->get_context()->remove_pre_shutdown_callback(
    *(handle.get()));
  node.get_clock()->wait_until_started();
  const auto result = handler.trigger(node.now());
  return_type status = return_type::OK;
  // a catch-all value to a scoped enumeration
  status = result.second;
  return needs_no_action(result.first) && qos_services.depth ? status : return_type::ERROR;
}
}  // namespace pkg
""")


def test_noetic_time_constants_and_distances_from_a_field_iterator(tmp_path):
    # forms of ros_controllers' joint_state and joint_trajectory controllers
    assert_parses_clean(tmp_path, r"""
#include <iterator>
#include <vector>
#include <ros/ros.h>
#include <trajectory_msgs/JointTrajectory.h>

double check(const trajectory_msgs::JointTrajectory & msg, std::vector<double> & v)
{
  typedef std::vector<trajectory_msgs::JointTrajectoryPoint>::const_iterator It;
  long n = 0;
  for (It it = msg.points.begin(); it != msg.points.end(); ++it) {
    n += std::distance(msg.points.begin(), it) + std::distance(it, msg.points.end());
  }
  n += std::distance(msg.points.begin(), msg.points.end()) + std::distance(v.begin(), v.end());
  const ros::Time last = ros::Time::MIN;
  return n + (last == ros::Time::ZERO) + ros::Duration::MAX.toSec();
}
""")


def test_a_switch_takes_a_message_field(tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/u_int8.hpp>
#include <planning_like/msg/state.hpp>

enum class Mode { Idle, Driving };

// a switch that is no field's still works in a constant expression
constexpr int weight(Mode mode)
{
  switch (mode) {
    case Mode::Driving:
      return 2;
    default:
      return 1;
  }
}
static_assert(weight(Mode::Driving) == 2, "a switch in a constant expression");

int react(const std_msgs::msg::UInt8 & msg, const planning_like::msg::State & state, Mode mode)
{
  switch (msg.data) {
    case 1:
      return 2;
    default:
      break;
  }
  switch (state.state) {
    case planning_like::msg::State::DRIVING:
      return 3;
  }
  // not a field: stays what it is, so its cases keep their enumeration
  switch(mode) {
    case Mode::Driving:
      return 4;
    default:
      return std::to_string(msg.data).size();
  }
}
""")


def test_function_templates_deduce_a_vector_from_a_field(tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <cstdio>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/point.hpp>
#include <nav_like/msg/path.hpp>
#include <std_msgs/msg/float64.hpp>

template <class T>
std::vector<T> resample(const std::vector<T> & points, double step);
template <class T>
double length(const std::vector<T> & points);

double run(const nav_like::msg::Path & path, const std_msgs::msg::Float64 & msg,
           rclcpp::Node & node)
{
  // what such a template returns converts on, and has a size
  std::vector<geometry_msgs::msg::Point> points = resample(path.points, 1.0);
  const auto coarse = resample(path.points, 2.0);
  // a field still passes through `...`
  std::printf("%f\n", msg.data);
  RCLCPP_INFO(node.get_logger(), "%f", msg.data);
  return length(path.points) + length(points) + coarse.size();
}
""")


def test_an_element_of_a_field_goes_into_sets_and_optionals(tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <optional>
#include <set>
#include <unordered_set>
#include <lanelet_like/lanelet.hpp>
#include <nav_like/msg/path.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>

std::optional<lanelet_like::Polygon3d> first(
  const nav_like::msg::Path & path, std::set<long> & ids, std::unordered_set<long> & seen,
  sensor_msgs::msg::LaserScan & scan)
{
  // an element still binds to a reference of a number
  for (float & range : scan.ranges) {
    range = 0.0f;
  }
  for (const auto & point : path.points) {
    for (const auto & lane_id : point.lane_ids) {
      ids.insert(lane_id);
      seen.insert(lane_id);
    }
  }
  for (const auto & polygon : path.polygons) {
    return polygon;
  }
  return {};
}
""")


def test_classes_of_unknown_libraries_are_made_from_braced_lists(tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <geo_like/geometry.hpp>
#include <nav_like/msg/path.hpp>

geo_like::LineString2d segment(const nav_like::msg::Path & path, const geo_like::Point2d & p)
{
  const auto & a = path.points.front();
  const geo_like::LineString2d line{{a.x, a.y}, {a.x + 1.0, a.y}};
  const geo_like::LineString2d mixed = {p, {a.x, a.y}};
  geo_like::LineString2d copy = line;
  geo_like::LineString2d one(p);
  copy = {};
  return {{a.x, a.y}, p};
}
""")


def test_static_assertions_on_stand_ins_are_no_errors(tmp_path):
    # they hold in the package's real build; the model's types differ
    assert_parses_clean(tmp_path, (
        '#include <cstdint>\n'
        '#include <type_traits>\n'
        '#include <sensor_msgs/msg/point_cloud2.hpp>\n'
        'static_assert(std::is_same<decltype(sensor_msgs::msg::PointCloud2()'
        '.height), uint32_t>::value, "height is 32 bits");\n'
        'template <class T> struct Buffer\n'
        '{\n'
        '  static_assert(sizeof(T) == 32, "a cloud is 32 bytes");\n'
        '};\n'
        'Buffer<sensor_msgs::msg::PointCloud2> buffer;\n'
        'void check() { static_assert(sizeof(buffer) > 0); }\n'))


def test_ros2_messages_keep_ros1s_pointer_names_and_qos_from_rmw(tmp_path):
    # rosidl still declares Ptr and ConstPtr (deprecated); a QoS is made
    # from an rmw profile through QoSInitialization::from_rmw
    assert_parses_clean(tmp_path, (
        '#include <rclcpp/rclcpp.hpp>\n'
        '#include <sensor_msgs/msg/point_cloud2.hpp>\n'
        'void on_cloud(const sensor_msgs::msg::PointCloud2::ConstPtr & msg);\n'
        'sensor_msgs::msg::PointCloud2::Ptr copy;\n'
        'sensor_msgs::msg::PointCloud2::ConstWeakPtr last;\n'
        'rclcpp::QoS qos(rclcpp::QoSInitialization::from_rmw(\n'
        '  rmw_qos_profile_sensor_data), rmw_qos_profile_sensor_data);\n'))


def test_typed_iterators_of_unknown_classes_and_one_argument_to_msg(tmp_path):
    # OpenCV's `image.begin<ushort>()`; tf2::toMsg of a tf2 type where only
    # <tf2/convert.h> is included (the overload is in tf2_geometry_msgs)
    assert_parses_clean(tmp_path, (
        '#include <algorithm>\n'
        '#include <vector>\n'
        '#include <opencv_like/core.hpp>\n'
        '#include <tf2/convert.h>\n'
        '#include <tf2/LinearMath/Quaternion.h>\n'
        '#include <geometry_msgs/Pose.h>\n'
        'void f(const opencv_like::Mat & image, const std::vector<double> & p,\n'
        '       const tf2::Quaternion & q)\n'
        '{\n'
        '  auto first = image.begin<unsigned short>();\n'
        '  auto last = std::unique(first, image.end<unsigned short>());\n'
        '  std::copy(p.begin(), p.end(), image.begin<double>());\n'
        '  geometry_msgs::Pose pose;\n'
        '  pose.orientation = tf2::toMsg(q);\n'
        '}\n'))


def test_a_constant_read_through_an_object_and_unknown_iterators(tmp_path):
    # `filter.UNKNOWN` (the package's struct) beside `Label::UNKNOWN` (a
    # message's constant); grid_map's iterator, of a library the model lacks
    assert_parses_clean(tmp_path, (
        '#include <cstdint>\n'
        '#include <perception_like_msgs/msg/object_classification.hpp>\n'
        '#include <grid_map_like/iterators.hpp>\n'
        'struct Filter { bool UNKNOWN; bool CAR; };\n'
        'using Label = perception_like_msgs::msg::ObjectClassification;\n'
        'bool is_target(const Filter & filter, const uint8_t label)\n'
        '{\n'
        '  return (label == Label::UNKNOWN && filter.UNKNOWN) ||\n'
        '    (label == Label::CAR && filter.CAR);\n'
        '}\n'
        'void walk(const grid_map_like::GridMap & map)\n'
        '{\n'
        '  for (grid_map_like::GridMapIterator it(map); !it.isPastEnd();'
        ' ++it) {}\n'
        '  grid_map_like::GridMapIterator back(map);\n'
        '  back--;\n'
        '}\n'))


def test_messages_of_a_type_compare_as_generated_messages_do(tmp_path):
    # rosidl and gencpp give every message == and !=; a state kept to
    # publish only on change compares the new one with the last
    assert_parses_clean(tmp_path, (
        '#include <memory>\n'
        '#include <optional>\n'
        '#include <adapi_like_msgs/msg/mrm_state.hpp>\n'
        '#include <legacy_msgs/ModeState.h>\n'
        'using MrmState = adapi_like_msgs::msg::MrmState;\n'
        'bool changed(const MrmState & now,\n'
        '             const std::shared_ptr<const MrmState> & last,\n'
        '             const std::optional<MrmState> & kept,\n'
        '             const legacy_msgs::ModeState & a,\n'
        '             const legacy_msgs::ModeStateConstPtr & b)\n'
        '{\n'
        '  return now != *last || kept != now || !(a == *b);\n'
        '}\n'))


def test_string_constants_and_members_taking_a_type_and_values(tmp_path):
    # a message's string constant (the stand-in knows only its name) against
    # a std::string; grid_map's `toImage<unsigned char, 3>(...)`, of a class
    # a repair declared, beside its type-only and value-only forms; Ogre's
    # begin with arguments; a field appended to a string; Boost.Asio's
    # older error_code forms
    assert_parses_clean(tmp_path, r"""
#include <string>
#include <boost/asio.hpp>
#include <planning_like_msgs/msg/scenario.hpp>
#include <grid_like/converter.hpp>
using Scenario = planning_like_msgs::msg::Scenario;
bool driving(std::string & current, const grid_like::Map & map,
             const Scenario & scenario)
{
  grid_like::Converter::toImage<unsigned char, 3>(map, "layer", 16);
  grid_like::Converter::toImage<float>(map);
  grid_like::Converter::toImage<2>(map);
  map.begin("BaseWhiteNoLighting", 2);
  for (const auto & cell : map) {}
  current += scenario.current_scenario;
  boost::asio::io_service io;
  boost::system::error_code error;
  io.run(error);
  if (error) {
    current += error.message();
  }
  return current == Scenario::LANEDRIVING || Scenario::PARKING != current;
}
""", {
        ('type', 'grid_like::Converter'),
        ('member-template', 'grid_like::Converter::toImage')})


def test_an_all_caps_name_of_an_unknown_library_is_a_constant(tmp_path):
    # ceres' enumerators, one without an underscore, beside its classes
    assert_parses_clean(tmp_path, (
        '#include <ceres_like/ceres.h>\n'
        'int configure(ceres_like::Problem & problem, bool cg)\n'
        '{\n'
        '  problem.setSolver(\n'
        '    cg ? ceres_like::CGNR : ceres_like::SPARSE_NORMAL_CHOLESKY);\n'
        '  const int type = ceres_like::CGNR;\n'
        '  return type;\n'
        '}\n'))


def test_every_form_of_rclcpps_logging_macros(tmp_path):
    # the stream forms build their text with an ostream
    assert_parses_clean(tmp_path, (
        '#include <string>\n'
        '#include <rclcpp/rclcpp.hpp>\n'
        'void report(rclcpp::Node & node, const std::string & frame)\n'
        '{\n'
        '  RCLCPP_ERROR_STREAM_THROTTLE(node.get_logger(), *node.get_clock(),'
        ' 1000, "no transform from " << frame);\n'
        '  RCLCPP_DEBUG_STREAM_ONCE(node.get_logger(), "frame " << frame);\n'
        '  RCLCPP_FATAL_STREAM_EXPRESSION(node.get_logger(), frame.empty(),'
        ' "empty " << frame);\n'
        '  RCLCPP_WARN_SKIPFIRST_THROTTLE(node.get_logger(), '
        '*node.get_clock(), 500, "late %s", frame.c_str());\n'
        '  RCLCPP_INFO_FUNCTION(node.get_logger(), nullptr, "%d", 1);\n'
        '}\n'))


def test_a_field_compares_with_an_optional_of_its_type(tmp_path):
    # std::optional's own comparisons with its value, not the catch-all's
    assert_parses_clean(tmp_path, (
        '#include <optional>\n'
        '#include <diag_like_msgs/msg/status.hpp>\n'
        'using Level = diag_like_msgs::msg::Status::_level_type;\n'
        'bool changed(const Level level, std::optional<Level> & last)\n'
        '{\n'
        '  if (level == last) return false;\n'
        '  last = level;\n'
        '  return last != level || level < 2;\n'
        '}\n'))
