# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The self-completing model mode, and failures that stay local."""

import re

from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.cpp.model_mode.recovery import kinds
from colcon_rsia.frontend.cpp.model_mode.recovery import rules
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.frontend.cpp.walker import _Walker
from colcon_rsia.package import analysis
from colcon_rsia.package import workers
from conftest import analyse_source
import pytest

# a ROS 2 node written against libraries the model does not have: OpenCV,
# Eigen, a base class from another library, a generated visibility header
DETECTOR = r"""
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <sensor_msgs/msg/image.hpp>
#include <opencv2/core.hpp>
#include <Eigen/Core>
#include <vision_core/filter_base.hpp>
#include "acme_vision/visibility_control.h"

namespace acme_vision
{

class ACME_VISION_PUBLIC Detector
  : public rclcpp::Node, public vision_core::FilterBase<float>
{
public:
  Detector() : Node("detector")
  {
    pub_ = create_publisher<std_msgs::msg::String>("detections", 10);
    sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image", 10,
      [this](sensor_msgs::msg::Image::ConstSharedPtr msg) { onImage(msg); });
  }

  void configure() override { threshold_ = CV_8UC1; }

private:
  void onImage(sensor_msgs::msg::Image::ConstSharedPtr msg)
  {
    cv::Mat_<float> kernel(3, 3);
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    geometry::shift(kernel, offset);
#if RSIA_TEST_VERSION_GTE(2, 0, 0)
    std_msgs::msg::String out;
    pub_->publish(out);
#endif
  }

  int threshold_ = 0;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr sub_;
};

}  // namespace acme_vision

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<acme_vision::Detector>());
  return 0;
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(acme_vision)
add_executable(detector_node src/detector_node.cpp)
"""


def _package(tmp_path):
    package = tmp_path / 'src' / 'acme_vision'
    (package / 'src').mkdir(parents=True)
    (package / 'src' / 'detector_node.cpp').write_text(DETECTOR)
    (package / 'CMakeLists.txt').write_text(CMAKE)
    return package


def _analyze(package, build_base, repair=analysis.REPAIR_ALWAYS):
    # the tests of what repairs declare have them made whether or not the
    # facts need them (see test_repair_only_when_it_pays)
    return analysis.analyze_package(
        name='acme_vision', path=str(package), build_base=str(build_base),
        jobs=1, header_mode='model',
        workspace_package_dirs=[str(package)], repair=repair)


def test_model_mode_repairs_what_unknown_libraries_leave_undeclared(
        tmp_path):
    package = _package(tmp_path)
    summary = _analyze(package, tmp_path / 'build' / 'acme_vision')

    [unit] = summary.coverage.units
    assert unit.file == 'src/detector_node.cpp'
    assert unit.package_errors == 0, summary.diagnostics
    assert unit.repair_rounds >= 1
    [node] = summary.nodes
    assert node.id == 'acme_vision/detector_node'
    [publisher] = node.publishers
    assert publisher.topic == 'detections'
    # published from the subscription's callback, inside the #if that
    # only the repaired function-like macro lets through
    assert publisher.label == 'dependent'
    assert len(publisher.publish_sites) == 1
    assert [s.topic for s in node.subscribers] == ['image']
    recorded = {(c.role, c.recorded) for c in summary.coverage.call_sites}
    assert recorded == {('publisher', 'node'), ('subscriber', 'node')}

    # the repairs are remembered: a second analysis (no cache) needs none
    again = analysis.analyze_package(
        name='acme_vision', path=str(package),
        build_base=str(tmp_path / 'build' / 'acme_vision'), jobs=1,
        header_mode='model', workspace_package_dirs=[str(package)],
        use_cache=False)
    [unit] = again.coverage.units
    assert (unit.package_errors, unit.repair_rounds) == (0, 0)


def _analyze_one_unit(tmp_path, code):
    """The summary of a package of this one source, and its unit."""
    package = tmp_path / 'src' / 'acme_vision'
    (package / 'src').mkdir(parents=True)
    (package / 'src' / 'detector_node.cpp').write_text(code)
    (package / 'CMakeLists.txt').write_text(CMAKE)
    summary = _analyze(package, tmp_path / 'build' / 'acme_vision')
    [unit] = summary.coverage.units
    return summary, unit


def _lines(text):
    lines = text.split('\n')

    def read_line(file, line):  # (as analysis.py's: '' past the end)
        return lines[line - 1] if 0 < line <= len(lines) else ''
    return read_line


@pytest.mark.parametrize('message,line,column,expected', [
    ("use of undeclared identifier 'cv'", 'cv::Mat m;', 1,
     {('namespace', 'cv')}),
    ("use of undeclared identifier 'CV_8UC1'", 'int t = CV_8UC1;', 9,
     {('constant', 'CV_8UC1')}),
    ("use of undeclared identifier 'FMT_COMPILE'",
     'auto s = fmt::format(FMT_COMPILE("{}"), x);', 22,
     {('macro-value', 'FMT_COMPILE')}),
    # the first template argument is a type (OpenCV's uchar)
    ("use of undeclared identifier 'uchar'",
     'auto p = src.at<Point3_<uchar>>(i);', 25, {('type', 'uchar')}),
    ("unknown type name 'FOO_PUBLIC'", 'class FOO_PUBLIC Bar {', 7,
     {('macro-empty', 'FOO_PUBLIC')}),
    ("unknown type name 'BOOST_CLASS_EXPORT'", 'BOOST_CLASS_EXPORT(Foo);', 1,
     {('macro-void', 'BOOST_CLASS_EXPORT')}),
    # a C library's functions (and macros) called: no classes
    ("use of undeclared identifier 'PyUnicode_AsEncodedString'",
     '  PyUnicode_AsEncodedString(name.ptr(), "UTF-8", "strict");', 3,
     {('function', 'PyUnicode_AsEncodedString')}),
    ("use of undeclared identifier 'PyBytes_AS_STRING'",
     '  names.push_back(PyBytes_AS_STRING(bytes));', 19,
     {('function', 'PyBytes_AS_STRING')}),
    # an unknown macro whose arguments read as calls
    ("called object type 'std::unordered_map<std::string, double> *' is not "
     'a function or function pointer',
     '  BOOST_SCOPE_EXIT((&processing_time_)(&stop_watch))', 39,
     {('macro-void', 'BOOST_SCOPE_EXIT')}),
    # an unknown C type as an array's element among template arguments
    ('expected expression', '  std::unique_ptr<nvmlProcessInfo_t[]> infos;',
     37, {('type', 'nvmlProcessInfo_t')}),
    ('expected expression', '  return values[];', 17, set()),
    # CUDA's attributes in a header a C++ unit includes
    ("variable has incomplete type 'void'", 'void __device__ setCell(', 6,
     {('macro-empty', '__device__')}),
    ("unknown type name '__host__'", '__host__ __device__ float half(float);',
     1, {('macro-empty', '__host__')}),
    ("unknown type name '__launch_bounds__'",
     '__launch_bounds__(256) void kernel();', 1,
     {('macro-void', '__launch_bounds__')}),
    ("unknown template name 'Controller'",
     'class C : public controller_interface::Controller<Iface> {', 40,
     {('template', 'controller_interface::Controller')}),
    ("no type named 'Vector3d' in namespace 'Eigen'",
     'Eigen::Vector3d v;', 8, {('type', 'Eigen::Vector3d')}),
    ("no member named 'LaterInfo' in namespace 'rclcpp'",
     'rclcpp::LaterInfo info;', 9, {('type', 'rclcpp::LaterInfo')}),
    # a name the model declares, used before the unit includes the model:
    # the model header, never a declaration that would clash with it
    ("no member named 'MatchedInfo' in namespace 'rclcpp'",
     'rclcpp::MatchedInfo info;', 9, {('header', 'rclcpp/rclcpp.hpp')}),
    ("no type named 'Transform' in namespace 'tf2'", 'tf2::Transform t;', 6,
     {('header', 'tf2/LinearMath/Transform.h')}),
    ("no member named 'get_value' in namespace 'acme'",
     'acme::get_value(3);', 7, {('function', 'acme::get_value')}),
    # boost::process's redirection compares: no template arguments open
    ("no member named 'std_in' in namespace 'boost::process'",
     '  bp::child c("grep", bp::std_out > out, bp::std_in < p);', 46,
     {('object', 'boost::process::std_in')}),
    # a statement clang reads as the declaration of `hull` (its message
    # says type): a lower-case name called is a function
    ("no type named 'correct' in namespace 'boost::geometry'",
     '  boost::geometry::correct(hull);', 20,
     {('function', 'boost::geometry::correct')}),
    ("no type named 'Polygon' in namespace 'geo'", '  geo::Polygon(hull);',
     8, {('type', 'geo::Polygon')}),
    ("function-like macro 'RCLCPP_VERSION_GTE' is not defined",
     '#if RCLCPP_VERSION_GTE(28, 0, 0)', 5,
     {('macro-condition', 'RCLCPP_VERSION_GTE')}),
    ("only virtual member functions can be marked 'override'",
     'void f() override;', 10, {('no-override', 'override')}),
    ('expected namespace name', 'namespace bacc = boost::accumulators;', 18,
     {('namespace', 'boost::accumulators')}),
    # templates whose use shows value arguments get value parameters
    ("no template named 'Matrix' in namespace 'Eigen'",
     'Eigen::Matrix<double, 3, 1> v;', 8, {('template:tvv', 'Eigen::Matrix')}),
    ("unknown template name 'Filter'", 'Filter<Eigen::Vector3d, N + 1> f;', 1,
     {('template:tv', 'Filter')}),
    ("unknown template name 'Buffer'",
     'Buffer<std::vector<int>, T> b;', 1, {('template', 'Buffer')}),
    # called with template arguments: a lowerCamelCase name is a function
    # template, a lower-case one may be a class (boost::optional<T>(x))
    ("no template named 'convertToPath' in namespace 'motion_utils'",
     'out = motion_utils::convertToPath<Path>(path);', 21,
     {('function', 'motion_utils::convertToPath')}),
    ("no template named 'convertToPoints' in namespace 'motion_utils'",
     'auto points = motion_utils::convertToPoints<', 29,
     {('function', 'motion_utils::convertToPoints')}),
    ("no template named 'optional' in namespace 'boost'",
     'return boost::optional<int>(x);', 15,
     {('template', 'boost::optional')}),
    # a value among the arguments: a function (a class would make a
    # declaration of `box` of the whole statement)
    ("no template named 'get' in namespace 'boost::geometry'",
     '      boost::geometry::get<boost::geometry::min_corner, 0>(box),', 24,
     {('function', 'boost::geometry::get')}),
    ("no template named 'array' in namespace 'acme'",
     '  auto a = acme::array<double, 3>{};', 18,
     {('template:tv', 'acme::array')}),
    # a standard template as its argument: range-v3's conversion
    ("no member named 'to' in namespace 'ranges'",
     '         ranges::to<std::vector>();', 18, {('function', 'ranges::to')}),
    ("no member named 'Identity' in 'Eigen::Matrix<double, 3, 3>'",
     'auto m = Eigen::Matrix<double, 3, 3>::Identity();', 39,
     {('member', 'Eigen::Matrix::Identity')}),
    ("no type named 'Ptr' in 'pcl::PointCloud<pcl::PointXYZ>'",
     'pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;', 33,
     {('member-type', 'pcl::PointCloud::Ptr')}),
    ("no member named 'Ptr' in 'pcl::PointCloud<pcl::PointXYZ>'",
     'pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new Cloud);', 33,
     {('member-type', 'pcl::PointCloud::Ptr')}),
    # a base class's function called as a statement: clang reads a
    # declaration of `source_view` first
    ("no type named 'mimic' in 'rviz_common::FramePositionTrackingView"
     "Controller'", '    FramePositionTrackingViewController::mimic('
     'source_view);', 42,
     {('member', 'rviz_common::FramePositionTrackingViewController::mimic')}),
    ("no type named 'Result' in 'acme::Buffer'", '    Buffer::Result(r);', 13,
     {('member-type', 'acme::Buffer::Result')}),
    # a nested type used as a scope: rviz's typedef of a base by itself
    ("no member named 'RTDClass' in 'rviz_common::RosTopicDisplay<"
     "acme_msgs::msg::Status>'", '    RosTopicDisplay::RTDClass::onInitialize();',
     22, {('member-scope', 'rviz_common::RosTopicDisplay::RTDClass')}),
    # the namespace of a header generated at build time (a parameter
    # library's ParamListener), named from the global namespace
    ("'gen_params' is not a class, namespace, or enumeration",
     'std::shared_ptr<::gen_params::ParamListener> listener_;', 20,
     {('namespace', 'gen_params')}),
    ("no member named 'gen_params' in the global namespace",
     'std::shared_ptr<::gen_params::ParamListener> listener_;', 20,
     {('namespace', 'gen_params')}),
    # a global function is no namespace: a function of a C library
    ("no member named 'helper' in the global namespace", '::helper(3);', 3,
     {('function', 'helper')}),
    ("no type named 'cudaError_t' in the global namespace",
     'const ::cudaError_t status = run();', 9, {('type', 'cudaError_t')}),
    ("no template named 'QMap'", '  QMap<IconState, QPixmap> icons;', 3,
     {('template', 'QMap')}),
    ("unexpected namespace name 'QFont': expected expression",
     'setFont(QFont("Roboto", 10, QFont::Bold));', 9, {('type', 'QFont')}),
    # a base class nothing declares
    ('expected class name', 'class CustomLabel : public QLabel', 27,
     {('type', 'QLabel')}),
    ('expected class name',
     'class View : public rviz_common::FramePositionTrackingViewController',
     21, {('type', 'rviz_common::FramePositionTrackingViewController')}),
    ('expected class name', 'struct Filter : public vision::Base<float>', 24,
     {('template', 'vision::Base')}),
    # (the column at the last part of the name)
    ('expected class name',
     'class View : public rviz_common::FramePositionTrackingViewController',
     34, {('type', 'rviz_common::FramePositionTrackingViewController')}),
    ('expected class name', 'class T : public Core, public ::testing::Test',
     42, {('type', 'testing::Test')}),
    # the type of a cast, not a local whose declaration failed
    ("use of undeclared identifier 'uchar'",
     'auto c = static_cast<uchar>(v);', 22, {('type', 'uchar')}),
    ("use of undeclared identifier 'uchar'", 'auto c = (uchar)v;', 11,
     {('type', 'uchar')}),
    # a CamelCase argument is a constant, a first template argument a type
    ("no member named 'InvalId' in namespace 'lanelet'",
     'auto bound = LineString3d(lanelet::InvalId, points);', 36,
     {('constant', 'lanelet::InvalId')}),
    ("no member named 'Dynamic' in namespace 'Eigen'",
     'Eigen::Matrix<float, Eigen::Dynamic, 1> v;', 30,
     {('type', 'Eigen::Dynamic')}),
    ("no member named 'Pose' in namespace 'geo'",
     'std::pair<geo::Pose, int> p;', 16, {('type', 'geo::Pose')}),
    # the first argument of a template is a type
    ("no member named 'uuid' in namespace 'boost::uuids'",
     'using Pair = std::pair<boost::uuids::uuid, int>;', 38,
     {('type', 'boost::uuids::uuid')}),
    # the C++ runtime's demangler, which real headers include on the way
    ("use of undeclared identifier 'abi'",
     'char * n = abi::__cxa_demangle(name, nullptr, nullptr, &status);', 12,
     {('std-header', 'cxxabi.h')}),
    # a macro taken for a function declaration
    ('expected function body after function declarator',
     'REGISTER_POINT_3D(Point, double, cs::cartesian, x, y, z)', 58,
     {('macro-void', 'REGISTER_POINT_3D')}),
    # a tag among template arguments is a type
    ("no member named 'cartesian' in namespace 'boost::geometry::cs'",
     'using P = bg::model::point<double, 2, bg::cs::cartesian>;', 48,
     {('type', 'boost::geometry::cs::cartesian')}),
    # a constant by its name stays a value
    ("no member named 'kSize' in namespace 'acme::limits'",
     'std::array<float, acme::limits::kSize> values;', 35,
     {('object', 'acme::limits::kSize')}),
    # a nested type of an unknown class, as a template argument
    ("no member named 'Result' in 'acme::Buffer'",
     'std::optional<acme::Buffer::Result>', 29,
     {('member-type', 'acme::Buffer::Result')}),
    # and one made of braces
    ("no member named 'Builder' in 'autoware::trajectory::Trajectory'",
     '  auto trajectory = trajectory::Trajectory<P>::Builder{}.build(points);', 48,
     {('member-type', 'autoware::trajectory::Trajectory::Builder')}),
    # a member of the catch-all base (a field named `type`) is no type
    ("typename specifier refers to non-type member 'type' in "
     "'pcl::traits::fieldList<pcl::PointXYZ>'",
     'typedef typename pcl::traits::fieldList<PointT>::type FieldList;', 50,
     {('member-type', 'pcl::traits::fieldList::type')}),
    # a function template called with explicit arguments
    ("use of undeclared identifier 'qobject_cast'",
     '  auto * button = qobject_cast<QPushButton *>(sender());', 19,
     {('function', 'qobject_cast')}),
    # a value before `&& !`: an enumerator, not an rvalue reference's type
    ("no member named 'LeftButton' in namespace 'Qt'",
     '  if (event->button() == Qt::LeftButton && !disabled) {', 30,
     {('constant', 'Qt::LeftButton')}),
    # a constant of a model header's list of externs, named before the
    # unit includes it
    ("no member named 'RGB8' in namespace 'sensor_msgs::image_encodings'",
     '  enc = sensor_msgs::image_encodings::RGB8;', 39,
     {('header', 'sensor_msgs/image_encodings.h')}),
    # a standard header the real headers would have brought in
    ('implicit instantiation of undefined template '
     "'std::basic_ifstream<char>'", '  std::ifstream file(path);', 17,
     {('std-header', 'fstream')}),
    # an enumerator of a global C enum of the model (rcl's clock types)
    ("use of undeclared identifier 'RCL_ROS_TIME'",
     '  rclcpp::Time t(stamp, RCL_ROS_TIME);', 25,
     {('header', 'rclcpp/rclcpp.hpp')}),
    # an enumerator of an unknown base class that a round made a class
    ("'Rotate2D' does not refer to a value", '    setCursor(Rotate2D);', 15,
     {('value', 'Rotate2D')}),
    # a user-defined literal of a library the model lacks (fmt's `_a`)
    ('no matching literal operator for call to \'operator""_a\' with '
     "arguments of types 'const char *' and 'unsigned long', and no "
     'matching literal operator template',
     '  fmt::print("{x}", "x"_a = 1);', 20, {('literal', '_a')}),
    # the package hashes a class a repair declared: no std::hash of ours
    ("redefinition of 'hash<lanelet::routing::LaneletPath>'",
     'struct hash<lanelet::routing::LaneletPath>', 8,
     {('no-hash', 'lanelet::routing::LaneletPath')}),
    # a function of the model, named before the unit includes the model
    ("no member named 'get_logger' in namespace 'rclcpp'",
     '  rclcpp::Logger logger_{rclcpp::get_logger("smoother")};', 35,
     {('header', 'rclcpp/rclcpp.hpp')}),
])
def test_repairs_from_one_diagnostic(message, line, column, expected):
    found = rules.repairs_from_diagnostics(
        [(message, 'a.cpp', 1, column)], _lines(line))
    assert found == expected


@pytest.mark.parametrize('code, expected', [
    # a local whose declaration failed: its own error says why
    ('const auto scan = to_scan(msg);\nuse(scan);\n', set()),
    ('for (const auto & scan : scans) {\nuse(scan);\n}\n', set()),
    # a name the code never declares: a library's constant or an unknown
    # base class's member
    ('void f(unsigned flag = scan);\nuse(scan);\n', {('object', 'scan')}),
    ('return scan;\nuse(scan);\n', {('object', 'scan')}),
])
def test_an_undeclared_variable_is_repaired_unless_the_code_declares_it(
        code, expected):
    line = code.split('\n').index('use(scan);') + 1
    found = rules.repairs_from_diagnostics(
        [("use of undeclared identifier 'scan'", 'a.cpp', line, 5)],
        lambda file, number: code.split('\n')[number - 1], texts=[code])
    assert found == expected


def test_a_template_argument_the_code_declares_a_variable_is_a_value():
    # `Eigen::Spline<double, 2, spline_dim>` with `constexpr auto
    # spline_dim = 3;` above: a lower-case name among template arguments
    # is a type (a tag) unless the code declares it a variable
    code = ('constexpr auto spline_dim = 3;\n'
            'auto s = Eigen::Spline<double, 2, spline_dim>(knots, points);\n'
            'using P = bg::model::point<double, 2, cartesian>;\n'
            # (an alias reads as a declaration of a variable too)
            'using point_t = bg::model::d2::point_xy<double>;\n'
            'using box_t = bg::model::box<point_t>;\n')
    messages = {
        ("no member named 'Spline' in namespace 'Eigen'", 2, 26):
            ('template:tvv', 'Eigen::Spline'),
        ("no template named 'Spline' in namespace 'Eigen'", 2, 26):
            ('template:tvv', 'Eigen::Spline'),
        ("no member named 'point' in namespace 'bg::model'", 3, 22):
            ('template:tvt', 'bg::model::point'),
        ("no member named 'box' in namespace 'bg::model'", 5, 26):
            ('template', 'bg::model::box')}
    for (message, line, column), expected in messages.items():
        found = rules.repairs_from_diagnostics(
            [(message, 'a.cpp', line, column)], _lines(code), texts=[code])
        assert found == {expected}, message


def test_the_packages_own_namespace_is_repaired_where_used_first():
    # `autoware` is the package's namespace too, but a header of a missing
    # library names it before any of the package's code opens it
    code = 'using autoware::kalman_filter::KalmanFilter;\n' \
        'namespace autoware::tracker { class Tracker {}; }\n'
    found = rules.repairs_from_diagnostics(
        [("use of undeclared identifier 'autoware'", 'a.h', 1, 7)],
        _lines(code.split('\n')[0]), texts=[code],
        declared=kinds.declared_names([code]))
    assert ('namespace', 'autoware') in found
    # nothing of the package's own is declared again
    assert not {name for _, name in found if 'Tracker' in name}


def test_a_function_brought_in_by_a_using_declaration_is_declared_there():
    # `using geo::calc;` alone looks like a value; the call that failed for
    # it shows a function, which a global declaration would conflict with
    lines = {1: 'using geo::calc;', 2: 'double d = calc(a, b);'}
    found = rules.repairs_from_diagnostics(
        [("no member named 'calc' in namespace 'geo'", 'a.cpp', 1, 12),
         ("use of undeclared identifier 'calc'", 'a.cpp', 2, 12)],
        lambda file, line: lines[line])
    assert found == {('function', 'geo::calc')}


def test_a_member_of_an_unknown_librarys_class_goes_into_its_repair():
    # pcl::PointCloud<P>::ConstPtr, where rsia_model/unknown/pcl.h declared
    # the class without it: the repair declares the class with the member
    message = "no type named 'ConstPtr' in 'pcl::PointCloud<pcl::PointXYZ>'"
    line = _lines('pcl::PointCloud<pcl::PointXYZ>::ConstPtr cloud;')
    found = rules.repairs_from_diagnostics(
        [(message, 'a.cpp', 1, 34)], line,
        stand_in=lambda relative: relative == 'rsia_model/unknown/pcl.h')
    assert found == {('member-type', 'pcl::PointCloud::ConstPtr'),
                     ('template', 'pcl::PointCloud')}
    # a class of a library we know nothing of is not declared again
    assert rules.repairs_from_diagnostics(
        [(message, 'a.cpp', 1, 34)], line, stand_in=lambda relative: False) \
        == {('member-type', 'pcl::PointCloud::ConstPtr')}


def test_a_scope_inside_a_repaired_class_is_a_nested_type(tmp_path):
    # `Estimator::Direction::MAXIMIZE`: clang says Direction is no scope
    header = tmp_path / 'repair.h'
    store.add_repairs(str(header), 'a.cpp', {
        ('type', 'Estimator'), ('namespace', 'Estimator::Direction')})
    assert store.read_repairs(str(header)) == {
        ('type', 'Estimator'), ('member-type', 'Estimator::Direction')}
    assert 'using Direction = ::rsia_model::Unknown;' in header.read_text()


def test_a_member_through_a_using_declared_class_is_the_classs(tmp_path):
    # `using ns::Estimator;` then `Estimator::Direction::MAXIMIZE`: an
    # earlier round took Direction for a value of ns::Estimator
    header = tmp_path / 'repair.h'
    store.add_repairs(str(header), 'a.cpp', {
        ('type', 'ns::Estimator'), ('member', 'ns::Estimator::Direction'),
        ('namespace', 'Estimator::Direction')})
    assert store.read_repairs(str(header)) == {
        ('type', 'ns::Estimator'), ('member-type', 'ns::Estimator::Direction')}
    text = header.read_text()
    assert 'using Direction = ::rsia_model::Unknown;' in text
    assert 'Any Direction' not in text


def test_constant_members_of_a_repaired_class_are_distinct_ints(tmp_path):
    # TensorRT's `case (nvinfer1::CalibrationAlgoType::kLEGACY_...):`
    header = tmp_path / 'repair.h'
    store.add_repairs(str(header), 'a.cpp', {
        ('type', 'trt::Algo'), ('member', 'trt::Algo::kLEGACY'),
        ('member', 'trt::Algo::kENTROPY'), ('member', 'trt::Algo::MAX_N'),
        ('member', 'trt::Algo::instance')})
    text = header.read_text()
    values = re.findall(r'static constexpr int (\w+) = (\d+);', text)
    assert {name for name, _ in values} == {'kLEGACY', 'kENTROPY', 'MAX_N'}
    assert len({value for _, value in values}) == 3
    assert 'static ::rsia_model::Any instance;' in text


def test_a_plural_beside_its_singular_is_a_vector_of_it(tmp_path):
    header = tmp_path / 'repair.h'
    store.add_repairs(str(header), 'a.cpp', {
        ('type', 'walls::VirtualWall'), ('type', 'walls::VirtualWalls'),
        ('type', 'walls::Status')})
    text = header.read_text()
    assert 'using VirtualWalls = std::vector<VirtualWall>;' in text
    assert 'struct VirtualWall :' in text
    assert 'struct Status :' in text  # no `Statu` to be a vector of


def test_a_repaired_class_has_pointer_types_of_its_own(tmp_path):
    header = tmp_path / 'repair.h'
    store.add_repairs(str(header), 'a.cpp', {
        ('template', 'pcl::PointCloud'), ('member-type', 'pcl::PointCloud::Ptr'),
        ('member-type', 'pcl::PointCloud::iterator')})
    text = header.read_text()
    # declared once, by the class itself, not as the catch-all member type
    assert text.count('using Ptr = ') == 1
    assert 'using Ptr = ::rsia_model::UnknownPointer<PointCloud>;' in text
    assert 'using iterator = ::rsia_model::Unknown;' in text
    store.add_repairs(str(header), 'a.cpp', {
        ('template', 'rviz_common::RosTopicDisplay'),
        ('member-scope', 'rviz_common::RosTopicDisplay::RTDClass'),
        ('member', 'rviz_common::RosTopicDisplay::RTDClass'),
        ('member', 'rviz_common::RosTopicDisplay::onInitialize')})
    text = header.read_text()
    # the class itself, whose members are declared with it
    assert 'using RTDClass = RosTopicDisplay;' in text
    assert 'static ::rsia_model::Any RTDClass;' not in text
    assert 'static ::rsia_model::Any onInitialize;' in text


def test_a_message_named_before_its_header_is_included_from_the_stand_ins():
    diagnostics = [("no type named 'Polygon' in namespace 'geometry_msgs::msg'",
                    'a.cpp', 1, 20)]
    line = _lines('geometry_msgs::msg::Polygon footprint;')
    # the stand-in exists: include it (a declaration would clash with it);
    # none yet: include it too, the analysis writes it with the repair (a
    # catch-all class would tie rclcpp::Time's conversion to the message
    # with its own constructor from anything)
    for exists in (True, False):
        assert rules.repairs_from_diagnostics(
            diagnostics, line, stand_in=lambda header: exists) == {
                ('header', 'geometry_msgs/msg/polygon.hpp')}
    # no stand-ins at all: declare the type
    assert rules.repairs_from_diagnostics(diagnostics, line) == {
        ('type', 'geometry_msgs::msg::Polygon')}


def test_a_new_namespace_gets_what_the_code_uses_of_it():
    text = ('karto::Pose2 pose;\n'
            'karto::LaserRangeFinder * laser = karto::make(3);\n'
            'int n = karto::MAX_RANGE + karto::Grid::Size;\n')
    found = rules.repairs_from_diagnostics(
        [("use of undeclared identifier 'karto'", 'a.cpp', 1, 1)],
        _lines(text), texts=[text])
    assert found == {
        ('namespace', 'karto'), ('type', 'karto::Pose2'),
        ('type', 'karto::LaserRangeFinder'), ('function', 'karto::make'),
        ('constant', 'karto::MAX_RANGE'), ('type', 'karto::Grid'),
        ('member', 'karto::Grid::Size')}


def test_names_the_package_declares_are_never_repaired():
    header = 'namespace karto {\nclass Transform\n{\n};\n}\n'
    declared = kinds.declared_names([header])
    found = rules.repairs_from_diagnostics(
        [("no type named 'Transform' in namespace 'karto'", 'a.cpp', 1, 8),
         ("no type named 'Transform' in namespace 'acme'", 'a.cpp', 2, 7)],
        _lines('karto::Transform a;\nacme::Transform b;'), declared=declared)
    # karto is the package's own namespace; acme's Transform is missing
    assert found == {('type', 'acme::Transform')}


def test_a_failing_declaration_loses_only_itself(tmp_path, monkeypatch):
    package = _package(tmp_path)
    original = _Walker._function

    def failing(walker, cursor):
        if cursor.spelling == 'onImage':
            raise RuntimeError('boom')
        return original(walker, cursor)
    monkeypatch.setattr(_Walker, '_function', failing)
    # the patch is in this process: parse here, not in worker processes
    monkeypatch.setattr(workers, 'START_METHOD', None)
    summary = _analyze(package, tmp_path / 'build' / 'acme_vision')
    [node] = summary.nodes
    # the constructor's facts survive; the publish site was in onImage
    assert [p.topic for p in node.publishers] == ['detections']
    assert node.publishers[0].publish_sites == []
    problems = [d for d in summary.diagnostics if 'onImage' in d]
    assert len(problems) == 1
    assert 'src/detector_node.cpp:' in problems[0]
    assert 'internal error: RuntimeError: boom' in problems[0]


def test_a_failing_unit_loses_only_itself(tmp_path, monkeypatch):
    package = _package(tmp_path)
    (package / 'src' / 'other.cpp').write_text(
        '#include <ros/ros.h>\nvoid advertise_status(ros::NodeHandle& nh)\n'
        '{\n  nh.advertise<std_msgs::String>("status", 1);\n}\n')
    original = cpp.extract_facts

    def failing(tu, *, package_path, source, **others):
        if source == 'src/other.cpp':
            raise RuntimeError('boom')
        return original(tu, package_path=package_path, source=source,
                        **others)
    monkeypatch.setattr(cpp, 'extract_facts', failing)
    monkeypatch.setattr(workers, 'START_METHOD', None)
    summary = _analyze(package, tmp_path / 'build' / 'acme_vision')
    assert [n.id for n in summary.nodes] == ['acme_vision/detector_node']
    assert any(d.startswith('src/other.cpp: not analysed (internal error: '
                            'RuntimeError: boom)')
               for d in summary.diagnostics)


def test_unresolved_callees_are_no_crash(tmp_path):
    # a call libclang cannot resolve (its callee undeclared) taking a
    # function of the package: the call's cursor references nothing
    package = tmp_path / 'pkg'
    (package / 'src').mkdir(parents=True)
    source = package / 'src' / 'node.cpp'
    source.write_text(
        '#include <ros/ros.h>\n'
        'void onTick(const ros::TimerEvent&) {}\n'
        'int main(int argc, char** argv)\n'
        '{\n'
        '  ros::init(argc, argv, "n");\n'
        '  ros::NodeHandle nh;\n'
        '  undeclared_helper(onTick, &onTick);\n'
        '  ros::Publisher p = nh.advertise<std_msgs::String>("out", 1);\n'
        '}\n')
    summary = analysis.analyze_package(
        name='pkg', path=str(package), build_base=str(tmp_path / 'build'),
        jobs=1, header_mode='model', workspace_package_dirs=[str(package)],
        repair=analysis.REPAIR_ALWAYS)
    assert not [d for d in summary.diagnostics if 'internal error' in d]
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['out']


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
    summary = analyse_source(tmp_path, 'watcher', NEWER_RCLCPP)
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
    summary = analyse_source(tmp_path, 'relay', TEMPLATED_HELPER)
    recorded = sorted((c.role, c.line, c.recorded)
                      for c in summary.coverage.call_sites)
    # both calls have facts (in the unit: the node's main reaches the
    # template constructor only through its instantiation)
    assert [(role, line) for role, line, _ in recorded] == [
        ('publisher', 11), ('subscriber', 12)]
    assert all(where != 'none' for _, _, where in recorded)


def test_call_sites_in_headers_no_unit_includes_are_not_counted(tmp_path):
    package = _package(tmp_path)
    (package / 'include' / 'acme_vision').mkdir(parents=True)
    # a header nothing includes: the build never compiles its code
    (package / 'include' / 'acme_vision' / 'unused.hpp').write_text(
        '#include <rclcpp/rclcpp.hpp>\n'
        'inline void unused(rclcpp::Node & node)\n'
        '{\n'
        '  node.create_publisher<std_msgs::msg::String>("never", 1);\n'
        '}\n')
    summary = _analyze(package, tmp_path / 'build' / 'acme_vision')
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
    summary = analyse_source(tmp_path, 'talker', LOST_CALL,
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
    package = _package(tmp_path)
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
          line.index(namespace) + 1)], _lines(line), texts=[line])
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
    summary = analyse_source(tmp_path, 'arm', HANDLES_AND_BUFFERS)
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
    summary = analyse_source(tmp_path, 'estimator', EIGEN_AND_CERES)
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
    summary = analyse_source(tmp_path, 'planner', PARAMETERS_TF2_PLUGINS)
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
    summary = analyse_source(tmp_path, 'braking', USING_AND_NESTED_TYPES)
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
    summary = analyse_source(tmp_path, 'monitor', FIELD_TYPES)
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
    line = _lines('auto r = lanelet.regulatoryElementsAs<Light>();')
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
    summary = analyse_source(tmp_path, 'relay', UNKNOWN_LIBRARY_TEMPLATES)
    assert not [d for d in summary.diagnostics if 'parse error' in d], \
        summary.diagnostics
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['lights']


ASSISTANT_HEADER = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Assistant
{
public:
  template <class NodeT>
  explicit Assistant(NodeT node);

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""

ASSISTANT_SOURCE = """
#include "assistant.hpp"

template <class NodeT>
Assistant::Assistant(NodeT node)
{
  pub_ = node->template create_publisher<std_msgs::msg::String>("graph", 1);
}

template Assistant::Assistant(rclcpp::Node::SharedPtr);
"""

MAPPER_MAIN = """
#include <memory>
#include "assistant.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("mapper");
  auto assistant = std::make_unique<Assistant>(node);
  rclcpp::spin(node);
  return 0;
}
"""


def test_a_helper_made_through_its_constructor_template_belongs_to_the_node(
        tmp_path):
    package = tmp_path / 'mapper'
    (package / 'include').mkdir(parents=True)
    (package / 'include' / 'assistant.hpp').write_text(ASSISTANT_HEADER)
    (package / 'src').mkdir()
    (package / 'src' / 'assistant.cpp').write_text(ASSISTANT_SOURCE)
    summary = analyse_source(tmp_path, 'mapper', MAPPER_MAIN)
    [node] = summary.nodes
    # the library's constructor runs only through make_unique<Assistant>:
    # a constructor template
    assert [p.topic for p in node.publishers] == ['graph']


def test_the_workspaces_own_copy_of_a_modelled_library_wins(tmp_path):
    from colcon_rsia.frontend.cpp import model_mode
    # a ros2_control checkout: its controller_interface/ headers are real
    library = tmp_path / 'ws' / 'controller_interface'
    header = 'controller_interface/controller_interface.hpp'
    (library / 'include' / 'controller_interface').mkdir(parents=True)
    (library / 'include' / header).write_text(
        '#include <acme_rt/handler.hpp>\n')
    package = tmp_path / 'ws' / 'my_controllers'
    (package / 'src').mkdir(parents=True)
    source = package / 'src' / 'c.cpp'
    source.write_text(f'#include <{header}>\n')
    arguments = model_mode.prepare_model_arguments(
        source=str(source), arguments=['-I', str(library / 'include')],
        package_path=str(package),
        workspace_package_dirs=[str(library), str(package)],
        stub_dir=str(tmp_path / 'stubs'))
    model = arguments.index(model_mode.MODEL_HEADERS_DIR)
    assert arguments.index(str(library / 'include')) < model
    # and its includes are followed there: what they lack is stood in
    assert (tmp_path / 'stubs' / 'acme_rt' / 'handler.hpp').is_file()


def test_call_sites_of_a_helper_defined_in_another_file(tmp_path):
    """A call of the package's helper is understood where the helper is.

    ``listener.subscribe(*node)`` creates a subscription in another file
    of the package: it is recorded there, and the call is understood
    through its call edge; a call of a same-named function that makes no
    endpoint stays a blind spot.
    """
    package = tmp_path / 'acme_watch'
    files = {
        'include/acme_watch/listener.hpp': (
            '#include <rclcpp/rclcpp.hpp>\n'
            '#include <std_msgs/msg/string.hpp>\n'
            'namespace acme_watch {\n'
            'class Listener {\n'
            'public:\n'
            '  void subscribe(rclcpp::Node & node);\n'
            '  void advertise(const std::string & what);\n'
            'private:\n'
            '  void on_status(const std_msgs::msg::String & msg);\n'
            '  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;\n'
            '};\n'
            '}  // namespace acme_watch\n'),
        'src/listener.cpp': (
            '#include "acme_watch/listener.hpp"\n'
            'namespace acme_watch {\n'
            'void Listener::subscribe(rclcpp::Node & node)\n'
            '{\n'
            '  sub_ = node.create_subscription<std_msgs::msg::String>(\n'
            '    "status", 1, [this](const std_msgs::msg::String & m) {\n'
            '      on_status(m); });\n'
            '}\n'
            'void Listener::advertise(const std::string & what)\n'
            '{\n'
            '  RCLCPP_INFO(rclcpp::get_logger("w"), "%s", what.c_str());\n'
            '}\n'
            'void Listener::on_status(const std_msgs::msg::String &) {}\n'
            '}  // namespace acme_watch\n'),
        'src/watcher.cpp': (
            '#include "acme_watch/listener.hpp"\n'
            'int main(int argc, char ** argv)\n'
            '{\n'
            '  rclcpp::init(argc, argv);\n'
            '  auto node = std::make_shared<rclcpp::Node>("watcher");\n'
            '  acme_watch::Listener listener;\n'
            '  listener.subscribe(*node);\n'
            '  listener.advertise("ready");\n'
            '  rclcpp::spin(node);\n'
            '}\n'),
        'CMakeLists.txt': (
            'cmake_minimum_required(VERSION 3.8)\n'
            'project(acme_watch)\n'
            'include_directories(include)\n'
            'add_library(listener src/listener.cpp)\n'
            'add_executable(watcher src/watcher.cpp)\n'
            'target_link_libraries(watcher listener)\n'),
    }
    for relative, text in files.items():
        (package / relative).parent.mkdir(parents=True, exist_ok=True)
        (package / relative).write_text(text)
    summary = analysis.analyze_package(
        name='acme_watch', path=str(package), build_base=str(tmp_path / 'b'),
        jobs=1, header_mode='model', workspace_package_dirs=[str(package)],
        repair=analysis.REPAIR_ALWAYS)
    recorded = sorted((c.file, c.line, c.role, c.recorded)
                      for c in summary.coverage.call_sites)
    assert recorded == [
        ('src/listener.cpp', 5, 'subscriber', 'node'),
        ('src/watcher.cpp', 7, 'subscriber', 'node'),
        ('src/watcher.cpp', 8, 'publisher', 'none')]


def test_facts_pair_with_the_call_sites_whose_expression_they_start():
    """A fact is located where its call starts, before the callee's name.

    ``twist_sub_ = Poller<M, P>::`` on line 13 and ``create_subscription(``
    on line 15 are a fact at 13 and a site at 15; the next call, written the same way over
    two lines, is a fact at 16 and a site at 17. Nearest-first per site
    would give the first site the fact of the second.
    """
    from colcon_rsia.package.call_sites import CallSite
    from colcon_rsia.package.coverage import match_sites
    sites = [CallSite('src/node.cpp', line, 'subscriber', 'create_subscription')
             for line in (15, 17, 18)]
    lines = {('src/node.cpp', 'subscriber'): [13, 16, 18]}
    assert match_sites(sites, lines) == set(sites)
    # a fact no site is near stays unmatched, and a site without one too
    assert match_sites(sites, {('src/node.cpp', 'subscriber'): [9, 18]}) == \
        {sites[2]}


def test_a_macro_called_in_a_macros_body_is_a_function_like_macro():
    # the error is at the outer macro's use, whose line does not show the
    # inner name; the body that calls it is among the texts
    code = ('#define REGISTER_STATE(ID, VALUE) REGISTER_ENTITY(ID, VALUE)\n'
            'void f() { REGISTER_STATE("state", x); }\n')
    lines = dict(enumerate(code.split('\n'), start=1))
    found = rules.repairs_from_diagnostics(
        [("use of undeclared identifier 'REGISTER_ENTITY'", 'a.cpp', 2, 12)],
        lambda file, line: lines[line], texts=[code])
    assert found == {('macro-value', 'REGISTER_ENTITY')}


def test_a_namespace_alias_is_repaired_through_its_target():
    # `namespace bg = boost::geometry;` failed while boost::geometry was
    # missing, and with it `bg::distance(a, b)`: a namespace bg would clash
    # with the alias once boost::geometry is declared
    code = 'namespace bg = boost::geometry;\ndouble d = bg::distance(a, b);\n'
    lines = dict(enumerate(code.split('\n'), start=1))
    found = rules.repairs_from_diagnostics(
        [('expected namespace name', 'a.cpp', 1, 16),
         ("use of undeclared identifier 'bg'", 'a.cpp', 2, 12)],
        lambda file, line: lines[line], texts=[code])
    assert ('namespace', 'bg') not in found
    assert ('namespace', 'boost::geometry') in found


def test_an_alias_taken_for_a_type_is_its_namespace():
    # `pt::ptree tree;` while the alias failed: clang says pt is an unknown
    # type; a class boost::property_tree would hide the namespace for good
    code = ('namespace pt = boost::property_tree;\n'
            'void f() { pt::ptree tree; }\n')
    lines = dict(enumerate(code.split('\n'), start=1))
    found = rules.repairs_from_diagnostics(
        [('expected namespace name', 'a.cpp', 1, 16),
         ("unknown type name 'pt'", 'a.cpp', 2, 12)],
        lambda file, line: lines[line], texts=[code])
    assert ('namespace', 'boost::property_tree') in found
    assert ('type', 'boost::property_tree') not in found
    assert ('type', 'boost::property_tree::ptree') in found


def test_the_namespaces_inside_a_repaired_one_are_repaired_at_once():
    # clang reports boost::geometry::model only once boost::geometry
    # exists, and so on: one parse per level, without this
    code = ('namespace bg = boost::geometry;\n'
            'using Point = bg::model::d2::point_xy<double>;\n')
    lines = dict(enumerate(code.split('\n'), start=1))
    found = rules.repairs_from_diagnostics(
        [('expected namespace name', 'a.cpp', 1, 16)],
        lambda file, line: lines[line], texts=[code])
    assert {('namespace', 'boost::geometry'),
            ('namespace', 'boost::geometry::model'),
            ('namespace', 'boost::geometry::model::d2'),
            ('template', 'boost::geometry::model::d2::point_xy')} <= found


def test_a_templates_arguments_past_its_line_still_shape_it():
    code = ('namespace bg = boost::geometry;\n'
            'const bg::strategy::transform::rotate_transformer<\n'
            '  bg::radian, double, 2, 2>\n'
            '  rotation(-angle);\n')
    lines = dict(enumerate(code.split('\n'), start=1))
    found = rules.repairs_from_diagnostics(
        [('expected namespace name', 'a.cpp', 1, 16)],
        lambda file, line: lines[line], texts=[code])
    assert ('template:ttvv',
            'boost::geometry::strategy::transform::rotate_transformer') \
        in found


def test_a_model_header_a_repair_includes_gets_its_stand_ins(tmp_path):
    # rclcpp is named before anything includes it (a header of an unknown
    # library would have): the repair includes the model's rclcpp.hpp,
    # which includes generated rcl_interfaces messages the unit's scan
    # never met; without them the parse stopped at a missing file
    summary, unit = _analyze_one_unit(tmp_path, (
        '#include <vendor_sdk/clock.hpp>\n'
        'double period() {\n'
        '  rclcpp::Duration d = rclcpp::Duration::from_seconds(0.5);\n'
        '  return d.seconds();\n'
        '}\n'))
    assert unit.repair_rounds >= 1
    assert unit.errors == 0, summary.diagnostics


PANEL = """\
#include <rviz_like/display.hpp>
#include <std_msgs/msg/string.hpp>

namespace acme_panels
{
class StatusDisplay : public rviz_like::Display
{
public:
  void onInitialize() override
  {
    // context_ is the unknown base class's member: a library constant or
    // member the code never declares is repaired as a catch-all value,
    // and the calls on it are known by their names
    auto ros_node = context_->getRosNodeAbstraction().lock();
    sub_ = ros_node->get_raw_node()->create_subscription<std_msgs::msg::String>(
      "status", 10, [this](std_msgs::msg::String::ConstSharedPtr msg) {
        text_ = msg->data;
      });
  }

private:
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  std::string text_;
};
}  // namespace acme_panels
"""


def test_calls_on_a_value_of_an_unknown_base_class_are_known_by_name(
        tmp_path):
    package = tmp_path / 'src' / 'acme_panels'
    (package / 'src').mkdir(parents=True)
    (package / 'src' / 'status_display.cpp').write_text(
        '#include <rclcpp/rclcpp.hpp>\n' + PANEL)
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(acme_panels)\n'
        'add_library(acme_panels SHARED src/status_display.cpp)\n')
    summary = analysis.analyze_package(
        name='acme_panels', path=str(package),
        build_base=str(tmp_path / 'build' / 'acme_panels'), jobs=1,
        header_mode='model', workspace_package_dirs=[str(package)],
        repair=analysis.REPAIR_ALWAYS)

    [unit] = summary.coverage.units
    assert unit.package_errors == 0, summary.diagnostics
    subscriptions = [c for c in summary.coverage.call_sites
                     if c.role == 'subscriber']
    # recorded as a fact ('unit': no node of the package runs it)
    assert [(c.line, c.recorded) for c in subscriptions] == [
        (16, 'unit')], summary.coverage.call_sites


def test_a_specialisation_of_an_unknown_function_template_is_repaired(
        tmp_path):
    # a library the model lacks declares `template <class T> IdType
    # customRegister(Registry &, const std::string &, const T *)`; the
    # package specialises it for its own type (ros2_control does, for
    # pal_statistics) and calls it
    summary, unit = _analyze_one_unit(tmp_path, (
        '#include <string>\n'
        '#include <vendor_stats/registry.hpp>\n'
        'struct Sample { double max; };\n'
        '/* namespace decoy { */\n'
        'namespace vendor_stats\n'
        '{\n'
        'namespace detail { int depth = 0; }\n'
        'template <>\n'
        'inline IdType customRegister(\n'
        '  Registry & registry, const std::string & name,\n'
        '  const Sample * sample, bool enabled)\n'
        '{\n'
        '  return registry.add(name + "/max", &sample->max, enabled);\n'
        '}\n'
        'template <>\n'
        'inline IdType customRegister<Sample>(Registry & registry)\n'
        '{\n'
        '  return registry.add("max");\n'
        '}\n'
        '}  // namespace vendor_stats\n'
        'void record(vendor_stats::Registry & registry, const Sample & s)\n'
        '{\n'
        '  vendor_stats::customRegister(registry, "sample", &s, true);\n'
        '  vendor_stats::customRegister<Sample>(registry);\n'
        '}\n'))
    assert unit.errors == 0, summary.diagnostics
    [header] = (tmp_path / 'build' / 'acme_vision').rglob(
        'repair/detector_node_cpp_*.h')
    assert ('specialized-function', 'vendor_stats::customRegister') in \
        store.read_repairs(str(header))


def test_streams_value_member_templates_and_casts_to_a_field_type(tmp_path):
    # boost::filesystem's ifstream, Eigen's fixed-size blocks and a cast to
    # a field's declared type, of libraries and messages the model lacks
    summary, unit = _analyze_one_unit(tmp_path, (
        '#include <string>\n'
        '#include <boost_like/filesystem.hpp>\n'
        '#include <eigen_like/core.hpp>\n'
        '#include <ctrl_like/msg/command.hpp>\n'
        'namespace fs = boost_like::filesystem;\n'
        'double run(const fs::path & path, ctrl_like::msg::Command & cmd,\n'
        '           const Eigen::Vector3d & point, Eigen::MatrixXd & cov)\n'
        '{\n'
        '  fs::ifstream ifs(path);\n'
        '  std::string line;\n'
        '  while (std::getline(ifs, line) && !line.empty()) {}\n'
        "  std::getline(ifs, line, ',');\n"
        '  const double velocity = 2.0;\n'
        '  cmd.velocity = static_cast<decltype(cmd.velocity)>(velocity);\n'
        '  cov.block<2, 2>(0, 0) = cov;\n'
        '  return point.head<2>().norm() + point.cast<float>().x() +\n'
        '    point.norm();\n'
        '}\n'))
    assert unit.errors == 0, summary.diagnostics


def test_a_widget_declared_with_qts_keywords_parses(tmp_path):
    # an rviz panel: Qt's widget headers are not in the model, its moc
    # keywords are
    summary, unit = _analyze_one_unit(tmp_path, (
        '#include <QPushButton>\n'
        '#include <QtWidgets/QWidget>\n'
        'class DoorPanel : public QWidget\n'
        '{\n'
        'public:\n'
        '  void update_doors(int count) { count_ = count; emit changed(); }\n'
        '\n'
        'Q_SIGNALS:\n'
        '  void changed();\n'
        '\n'
        'private slots:\n'
        '  void on_button(unsigned index);\n'
        '\n'
        'private:\n'
        '  QPushButton * button_ = nullptr;\n'
        '  int count_ = 0;\n'
        '};\n'
        'void DoorPanel::on_button(unsigned index) { update_doors(index); }\n'))
    assert unit.package_errors == 0, summary.diagnostics


def test_a_name_among_a_macros_arguments_on_a_later_line():
    # clang gives the line the macro's call starts on; the name is on one
    # of the lines its arguments go on to
    lines = _lines(
        '  CHECK_CUDA_ERROR(cudaMemcpy(\n'
        '    device_ptr, host.data(),\n'
        '    host.size() * sizeof(float), cudaMemcpyHostToDevice));\n'
        '  kernel(cudaMemcpyHostToDevice);')
    diagnostics = [(
        "use of undeclared identifier 'cudaMemcpyHostToDevice'", 'a.cu', 1,
        3)]
    assert rules.repairs_from_diagnostics(diagnostics, lines) == {
        ('object', 'cudaMemcpyHostToDevice')}
    # spelled in the body of a macro: no later line of the call has it
    lines = _lines('  LOG_FAILURE(code);\n  next(code);')
    diagnostics = [("use of undeclared identifier 'logging'", 'a.cpp', 1, 3)]
    assert rules.repairs_from_diagnostics(diagnostics, lines) == {
        ('namespace', 'logging')}


def test_point_cloud_filters_cuda_calls_and_eigen_containers_parse(tmp_path):
    # what autoware's NDT and lidar packages write with PCL, Eigen and
    # CUDA, none of them in the model: traits of a class template, its
    # pointer types, an allocator, an index type, static assertions on a
    # point type's layout, a macro's call over several lines, and a time
    # passed as a message before the message's header is included
    summary, unit = _analyze_one_unit(tmp_path, (
        '#include <cstddef>\n'
        '#include <vector>\n'
        '#include <pcl/filters/voxel_grid.h>\n'
        '#include <pcl/registration/registration.h>\n'
        '#include <Eigen/Core>\n'
        '#include <cuda_runtime_api.h>\n'
        '#include <rclcpp/rclcpp.hpp>\n'
        '#include <std_srvs/srv/trigger.hpp>\n'
        '#define CHECK_CUDA_ERROR(e) (e)\n'
        'struct LidarPoint { float x; lidar_types::Stamp t; float y; };\n'
        'static_assert(offsetof(LidarPoint, y) == 12, "layout");\n'
        'template <typename PointT>\n'
        'class Grid : public pcl::VoxelGrid<PointT>\n'
        '{\n'
        '  typedef typename pcl::traits::fieldList<PointT>::type FieldList;\n'
        '  typedef pcl::Registration<PointT, PointT> Base;\n'
        '  typedef typename Base::PointCloudSource Source;\n'
        '  typedef typename Source::Ptr SourcePtr;\n'
        'public:\n'
        '  pcl::PointCloud<PointT> cloud(const SourcePtr & source) const\n'
        '  {\n'
        '    pcl::shared_ptr<pcl::PointCloud<PointT>> out(\n'
        '      new pcl::PointCloud<PointT>);\n'
        '    return *source;\n'
        '  }\n'
        '};\n'
        'float stamped(const builtin_interfaces::msg::Time & stamp);\n'
        'void upload(float * device, const std::vector<float> & host,\n'
        '            const rclcpp::Time & now,\n'
        '            rclcpp::Client<std_srvs::srv::Trigger> & client)\n'
        '{\n'
        '  CHECK_CUDA_ERROR(cudaMemcpy(\n'
        '    device, host.data(),\n'
        '    host.size() * sizeof(float), cudaMemcpyHostToDevice));\n'
        '  stamped(now);\n'
        '  auto result = client.async_send_request(\n'
        '    std::make_shared<std_srvs::srv::Trigger::Request>(),\n'
        '    [](rclcpp::Client<std_srvs::srv::Trigger>::SharedFuture) {});\n'
        '  result.wait_for(std::chrono::seconds(0));\n'
        '}\n'))
    assert unit.package_errors == 0, summary.diagnostics


def test_a_module_macros_body_is_a_function(tmp_path):
    # pybind11's module macro, unknown to the model, with its body's
    # braces on the next line: its second argument is the module object
    # the body uses; the node's publisher in the same unit is kept
    summary, unit = _analyze_one_unit(tmp_path, (
        '#include <pybind11/pybind11.h>\n'
        '#include <rclcpp/rclcpp.hpp>\n'
        '#include <std_msgs/msg/float64.hpp>\n'
        'struct Gains { double kp; };\n'
        'class Tuner : public rclcpp::Node\n'
        '{\n'
        'public:\n'
        '  Tuner() : Node("tuner")\n'
        '  {\n'
        '    pub_ = create_publisher<std_msgs::msg::Float64>("gain", 1);\n'
        '  }\n'
        '  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;\n'
        '};\n'
        'namespace py = pybind11;\n'
        'PYBIND11_MODULE(acme_tuner, m)\n'
        '{\n'
        '  py::class_<Gains>(m, "Gains").def(py::init<>())\n'
        '    .def_readwrite("kp", &Gains::kp);\n'
        '}\n'
        'PYBIND11_MODULE(acme_other, m) {\n'
        '  m.doc() = "second module";\n'
        '}\n'))
    assert unit.package_errors == 0, summary.diagnostics
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['gain']
    lines = _lines('PYBIND11_MODULE(acme_tuner, m)\n{')
    diagnostics = [('expected unqualified-id', 'a.cpp', 1, 1)]
    assert rules.repairs_from_diagnostics(diagnostics, lines) == {
        ('macro-function', 'PYBIND11_MODULE')}
    # without a body, still a statement-like declaration
    lines = _lines(
        'BOOST_GEOMETRY_REGISTER_POINT_2D(P, double, cs, x, y)\n'
        'namespace acme {')
    diagnostics = [('expected unqualified-id', 'a.cpp', 1, 1)]
    assert rules.repairs_from_diagnostics(diagnostics, lines) == set()


def test_headers_beside_a_subdirectorys_sources_are_found(tmp_path):
    # a library in a subdirectory whose CMake adds its `src` directory
    # (`target_include_directories(rules PUBLIC src)` there): its sources
    # include "rule_helper/area.hpp" from it
    package = tmp_path / 'src' / 'acme_vision'
    helper = package / 'rules' / 'src' / 'rule_helper'
    helper.mkdir(parents=True)
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\n'
        'project(acme_vision)\n'
        'add_subdirectory(rules)\n')
    (package / 'rules' / 'CMakeLists.txt').write_text(
        'add_library(rules src/rule_helper/area.cpp)\n'
        'target_include_directories(rules PUBLIC src)\n')
    (helper / 'area.hpp').write_text(
        '#include <rclcpp/rclcpp.hpp>\n'
        '#include <std_msgs/msg/string.hpp>\n'
        'namespace rule_helper\n'
        '{\n'
        'class Area\n'
        '{\n'
        'public:\n'
        '  explicit Area(rclcpp::Node & node);\n'
        'private:\n'
        '  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;\n'
        '};\n'
        '}  // namespace rule_helper\n')
    (helper / 'area.cpp').write_text(
        '#include "rule_helper/area.hpp"\n'
        'namespace rule_helper\n'
        '{\n'
        'Area::Area(rclcpp::Node & node)\n'
        '{\n'
        '  pub_ = node.create_publisher<std_msgs::msg::String>("area", 1);\n'
        '}\n'
        '}  // namespace rule_helper\n')
    summary = _analyze(package, tmp_path / 'build' / 'acme_vision')
    [unit] = summary.coverage.units
    assert unit.file == 'rules/src/rule_helper/area.cpp'
    assert unit.package_errors == 0, summary.diagnostics
    recorded = {(c.role, c.recorded) for c in summary.coverage.call_sites}
    # a library's: its facts are the unit's, no node of its own runs them
    assert recorded == {('publisher', 'unit')}, summary.coverage.call_sites


def test_headers_of_the_packages_src_are_found_from_a_subdirectory(
        tmp_path):
    # example_rule/'s sources include "switch_rule/base_rule.hpp" of the
    # package's src/ (its CMake: target_include_directories(x PUBLIC src))
    package = tmp_path / 'src' / 'acme_vision'
    (package / 'src' / 'switch_rule').mkdir(parents=True)
    (package / 'example_rule' / 'src').mkdir(parents=True)
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\n'
        'project(acme_vision)\n'
        'add_library(acme_vision INTERFACE)\n'
        'target_include_directories(acme_vision INTERFACE src)\n'
        'add_subdirectory(example_rule)\n')
    (package / 'example_rule' / 'CMakeLists.txt').write_text(
        'add_library(rules src/rule.cpp)\n'
        'target_link_libraries(rules acme_vision)\n')
    (package / 'src' / 'switch_rule' / 'base_rule.hpp').write_text(
        '#include <vector>\n'
        'namespace switch_rule\n'
        '{\n'
        'struct BaseRule\n'
        '{\n'
        '  using Markers = std::vector<int>;\n'
        '  virtual Markers markers() { return Markers{}; }\n'
        '};\n'
        '}  // namespace switch_rule\n')
    (package / 'example_rule' / 'src' / 'rule.cpp').write_text(
        '#include "switch_rule/base_rule.hpp"\n'
        'namespace switch_rule\n'
        '{\n'
        'struct MapRule : BaseRule\n'
        '{\n'
        '  Markers markers() override;\n'
        '};\n'
        'MapRule::Markers MapRule::markers() { return {1, 2}; }\n'
        '}  // namespace switch_rule\n')
    summary = _analyze(package, tmp_path / 'build' / 'acme_vision')
    [unit] = summary.coverage.units
    assert unit.file == 'example_rule/src/rule.cpp'
    assert (unit.package_errors, unit.repair_rounds) == (0, 0), \
        summary.diagnostics


def test_a_name_that_ends_its_line_is_known_by_the_next_one():
    # `cond ? Qt::ForbiddenCursor` goes on with `: Qt::ArrowCursor`: a
    # value, as `Qt::ForbiddenCursor :` on one line would be
    lines = _lines(
        '  setCursor(disabled ? Qt::ForbiddenCursor\n'
        '                     : Qt::ArrowCursor);')
    diagnostics = [("no member named 'ForbiddenCursor' in namespace 'Qt'",
                    'a.cpp', 1, 29)]
    assert rules.repairs_from_diagnostics(diagnostics, lines) == {
        ('constant', 'Qt::ForbiddenCursor')}
    # and a type at the end of its line stays one
    lines = _lines('  std::unique_ptr<acme::Device>\n    device_;')
    diagnostics = [("no member named 'Device' in namespace 'acme'",
                    'a.cpp', 1, 25)]
    assert rules.repairs_from_diagnostics(diagnostics, lines) == {
        ('type', 'acme::Device')}


def test_an_attribute_macro_before_a_class_name_is_empty():
    # `struct EIGEN_ALIGN16 Point {` reads as a variable of an incomplete
    # `struct EIGEN_ALIGN16`
    diagnostics = [("variable has incomplete type 'struct EIGEN_ALIGN16'",
                    'a.cpp', 1, 8)]
    assert rules.repairs_from_diagnostics(
        diagnostics, _lines('struct EIGEN_ALIGN16 LivoxPoint')) == {
            ('macro-empty', 'EIGEN_ALIGN16')}


def test_a_member_of_an_unknown_base_multiplied_is_no_local():
    # `size_x_ * resolution_` multiplies a member the unknown base class
    # (nav2_costmap_2d::Costmap2D) has; `Cell * cell_` would declare one
    code = ('void Grid::update(double wx)\n'
            '{\n'
            '  // the origin_x_ of the world\n'
            '  const double end = origin + size_x_ * resolution_;\n'
            '  int mx = static_cast<int>((wx - origin_x_) / resolution_);\n'
            '}\n')
    lines = _lines(code)
    for name, line, column in (('resolution_', 4, 41), ('origin_x_', 5, 36)):
        diagnostics = [(f"use of undeclared identifier '{name}'", 'a.cpp',
                        line, column)]
        assert rules.repairs_from_diagnostics(
            diagnostics, lines, texts=[code]) == {('object', name)}
    code = 'void f()\n{\n  Cell * cell_ = find();\n  use(cell_);\n}\n'
    diagnostics = [("use of undeclared identifier 'cell_'", 'a.cpp', 4, 7)]
    assert rules.repairs_from_diagnostics(
        diagnostics, _lines(code), texts=[code]) == set()


def test_a_repaired_class_is_hashed_unless_the_package_hashes_it(tmp_path):
    header = tmp_path / 'repair.h'
    store.add_repairs(str(header), 'a.cpp', {
        ('type', 'boost::uuids::uuid'),
        ('type', 'lanelet::routing::LaneletPath'),
        ('no-hash', 'lanelet::routing::LaneletPath'), ('literal', '_a')})
    text = header.read_text()
    assert 'struct std::hash<::boost::uuids::uuid>' in text
    assert 'std::hash<::lanelet::routing::LaneletPath>' not in text
    assert '::rsia_model::Any& operator""_a(const char*, unsigned long);' \
        in text


def test_a_static_member_template_of_a_repaired_namespaces_class():
    # the namespace's uses are repaired at once: `toImage<uint16_t, 1>`
    # is a member template, not a value
    code = ('void f(const Map & map, Image & image)\n'
            '{\n'
            '  grid_map::GridMapCvConverter::toImage<uint16_t, 1>(\n'
            '    map, "elevation", image);\n'
            '}\n')
    diagnostics = [("use of undeclared identifier 'grid_map'", 'a.cpp', 3, 3)]
    assert rules.repairs_from_diagnostics(
        diagnostics, _lines(code), texts=[code]) == {
            ('namespace', 'grid_map'),
            ('type', 'grid_map::GridMapCvConverter'),
            ('member-template', 'grid_map::GridMapCvConverter::toImage')}


def test_a_value_used_with_template_arguments_becomes_a_function(tmp_path):
    # `using boost::geometry::return_centroid;` read as a value, then
    # `return_centroid<Point2d>(polygon)`
    header = tmp_path / 'repair.h'
    store.add_repairs(str(header), 'a.cpp', {
        ('object', 'boost::geometry::return_centroid')})
    assert store.add_repairs(str(header), 'a.cpp', {
        ('template-use', 'return_centroid')})
    assert store.read_repairs(str(header)) == {
        ('function', 'boost::geometry::return_centroid')}


def test_a_comparison_declares_no_variable():
    # `cell_size_y > size_y_` compares a member of the unknown base class;
    # `std::vector<int> cells_;` declares one
    code = ('void Grid::move()\n'
            '{\n'
            '  if (start_y + cell_size_y > size_y_) {}\n'
            '  int size_y{static_cast<int>(size_y_)};\n'
            '}\n')
    diagnostics = [("use of undeclared identifier 'size_y_'", 'a.cpp', 4, 30)]
    assert rules.repairs_from_diagnostics(
        diagnostics, _lines(code), texts=[code]) == {('object', 'size_y_')}
    code = 'void f()\n{\n  std::vector<int> cells_;\n  use(cells_);\n}\n'
    diagnostics = [("use of undeclared identifier 'cells_'", 'a.cpp', 4, 7)]
    assert rules.repairs_from_diagnostics(
        diagnostics, _lines(code), texts=[code]) == set()


def test_an_alias_of_its_namesake_declares_nothing_of_the_package():
    # the package opens a `namespace pcl` of its own (for a point type) and
    # aliases pcl's names: pcl::PointCloud is still pcl's, and missing
    declared = kinds.declared_names([
        'namespace pcl\n{\nstruct PointXYZIR {};\n}\n'
        'class Filter\n{\n'
        '  using PointCloud = pcl::PointCloud<pcl::PointXYZ>;\n'
        '  typedef pcl :: IndicesPtr IndicesPtr;\n'
        '  using Cloud = pcl::PointCloud<pcl::PointXYZ>;\n'
        '  typedef std::vector<int> Indices;\n'
        '};\n'])
    assert {'pcl', 'PointXYZIR', 'Filter', 'Cloud', 'Indices'} <= declared
    assert not {'PointCloud', 'IndicesPtr'} & declared
    diagnostics = [("no template named 'PointCloud' in namespace 'pcl'",
                    'a.hpp', 1, 27)]
    assert rules.repairs_from_diagnostics(
        diagnostics,
        _lines('  using PointCloud = pcl::PointCloud<pcl::PointXYZ>;'),
        declared=declared) == {('template', 'pcl::PointCloud')}


def test_a_name_the_package_declares_in_another_namespace_is_repaired():
    # the package's `using Trajectory = autoware::trajectory::Trajectory<P>;`
    # inside its own `namespace autoware::planning` declares no
    # autoware::trajectory::Trajectory
    declared = kinds.declared_names([
        'namespace autoware::planning\n{\n'
        'class Module\n{\n'
        '  using Trajectory = autoware::trajectory::Trajectory<Point>;\n'
        '};\n}\n'])
    assert {'autoware', 'planning', 'Module'} <= declared
    line = _lines(
        '  using Trajectory = autoware::trajectory::Trajectory<Point>;')
    diagnostics = [("no template named 'Trajectory' in namespace "
                    "'autoware::trajectory'", 'a.hpp', 1, 44)]
    assert rules.repairs_from_diagnostics(
        diagnostics, line, declared=declared) == {
            ('template', 'autoware::trajectory::Trajectory')}
    # one in the package's own namespaces stays the package's
    diagnostics = [("no member named 'Module' in namespace "
                    "'autoware::planning'", 'a.hpp', 1, 1)]
    assert rules.repairs_from_diagnostics(
        diagnostics, _lines('autoware::planning::Module m;'),
        declared=declared) == set()
