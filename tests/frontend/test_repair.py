# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The self-completing model mode, and failures that stay local."""

import re

from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.cpp.model_mode import model_index
from colcon_rsia.frontend.cpp.model_mode.recovery import rules
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.frontend.cpp.walker import _Walker
from colcon_rsia.package import analysis
from colcon_rsia.package import workers
from model_sources import acme_vision_package
from model_sources import analyze_acme_vision
from model_sources import line_reader
import pytest


def test_model_mode_repairs_what_unknown_libraries_leave_undeclared(
        tmp_path):
    package = acme_vision_package(tmp_path)
    summary = analyze_acme_vision(package, tmp_path / 'build' / 'acme_vision')

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
        [(message, 'a.cpp', 1, column)], line_reader(line))
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
            [(message, 'a.cpp', line, column)], line_reader(code), texts=[code])
        assert found == {expected}, message


def test_the_packages_own_namespace_is_repaired_where_used_first():
    # `autoware` is the package's namespace too, but a header of a missing
    # library names it before any of the package's code opens it
    code = 'using autoware::kalman_filter::KalmanFilter;\n' \
        'namespace autoware::tracker { class Tracker {}; }\n'
    found = rules.repairs_from_diagnostics(
        [("use of undeclared identifier 'autoware'", 'a.h', 1, 7)],
        line_reader(code.split('\n')[0]), texts=[code],
        declared=model_index.declared_names([code]))
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
    line = line_reader('pcl::PointCloud<pcl::PointXYZ>::ConstPtr cloud;')
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
    line = line_reader('geometry_msgs::msg::Polygon footprint;')
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
        line_reader(text), texts=[text])
    assert found == {
        ('namespace', 'karto'), ('type', 'karto::Pose2'),
        ('type', 'karto::LaserRangeFinder'), ('function', 'karto::make'),
        ('constant', 'karto::MAX_RANGE'), ('type', 'karto::Grid'),
        ('member', 'karto::Grid::Size')}


def test_names_the_package_declares_are_never_repaired():
    header = 'namespace karto {\nclass Transform\n{\n};\n}\n'
    declared = model_index.declared_names([header])
    found = rules.repairs_from_diagnostics(
        [("no type named 'Transform' in namespace 'karto'", 'a.cpp', 1, 8),
         ("no type named 'Transform' in namespace 'acme'", 'a.cpp', 2, 7)],
        line_reader('karto::Transform a;\nacme::Transform b;'), declared=declared)
    # karto is the package's own namespace; acme's Transform is missing
    assert found == {('type', 'acme::Transform')}


def test_a_failing_declaration_loses_only_itself(tmp_path, monkeypatch):
    package = acme_vision_package(tmp_path)
    original = _Walker._function

    def failing(walker, cursor):
        if cursor.spelling == 'onImage':
            raise RuntimeError('boom')
        return original(walker, cursor)
    monkeypatch.setattr(_Walker, '_function', failing)
    # the patch is in this process: parse here, not in worker processes
    monkeypatch.setattr(workers, 'START_METHOD', None)
    summary = analyze_acme_vision(package, tmp_path / 'build' / 'acme_vision')
    [node] = summary.nodes
    # the constructor's facts survive; the publish site was in onImage
    assert [p.topic for p in node.publishers] == ['detections']
    assert node.publishers[0].publish_sites == []
    problems = [d for d in summary.diagnostics if 'onImage' in d]
    assert len(problems) == 1
    assert 'src/detector_node.cpp:' in problems[0]
    assert 'internal error: RuntimeError: boom' in problems[0]


def test_a_failing_unit_loses_only_itself(tmp_path, monkeypatch):
    package = acme_vision_package(tmp_path)
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
    summary = analyze_acme_vision(package, tmp_path / 'build' / 'acme_vision')
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
