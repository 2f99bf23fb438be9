# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Real code's idioms parse in model mode: unknown libraries, catch-alls."""


from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.cpp.model_mode import source_names
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from model_sources import assert_parses_clean
from model_sources import parse_unit
from model_sources import prepare_model_arguments
from model_sources import write_sources
import pytest


def test_real_code_idioms_type_check_without_repairs(tmp_path):
    # what autoware-style code does with the ROS model and libraries the
    # model lacks; each line was a parse error before the model took it
    package, [source] = write_sources(tmp_path, node=r"""
#include <algorithm>
#include <chrono>
#include <vector>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/header.hpp>
#include <std_srvs/srv/trigger.hpp>
#include <tf2/LinearMath/Quaternion.h>
#include <geo_utils/stop_watch.hpp>
#include <geo_utils/geometry.hpp>

using geo_utils::StopWatch;
using geo_utils::motion::calc_length;

double run(const std_msgs::msg::Header & header, rclcpp::Node & node,
           const geo_utils::Vector2d & a, const geo_utils::Vector2d & b)
{
  // a class template and a function template of an unknown library
  StopWatch<std::chrono::milliseconds> stop_watch;
  const bool enabled = geo_utils::get_or_declare<bool>(node, "enabled");
  // arithmetic and comparisons on its classes
  geo_utils::Vector2d d = a - b;
  const bool same = a == b;
  // a vector of its class filled from a catch-all value
  std::vector<geo_utils::Polygon> polygons;
  polygons.push_back(geo_utils::make_polygon(d));
  // a time from now minus a message's stamp, a field against a number
  const double age = (node.now() - header.stamp).seconds();
  const double capped = std::min(header.stamp.sec, 10);
  // a message's SharedPtr from a polling subscriber of that library
  std_msgs::msg::Header::ConstSharedPtr last;
  last = geo_utils::poller.take_data();
  // a pointer of that library, and a string made from a field
  geo_utils::PortHandler * port = geo_utils::PortHandler::getPortHandler(
    header.frame_id);
  const std::string frame(header.frame_id);
  // rclcpp and tf2 members real code uses
  const rclcpp::Duration timeout(header.stamp);
  node.get_logger().set_level(rclcpp::Logger::Level::Debug);
  rclcpp::Service<std_srvs::srv::Trigger>::CallbackType on_trigger;
  const tf2::Quaternion q(0, 0, 0, 1);
  const double w = q.getW() + timeout.seconds();
  // a function of a namespace inside it, also through a using-declaration
  const double length = calc_length(d) + geo_utils::motion::calc_length(d);
  return enabled && same && port && !frame.empty() && on_trigger ?
         age + length + w : capped;
}
""")
    stub_dir = tmp_path / 'stubs'
    arguments = prepare_model_arguments(package, source, stub_dir)
    unknown = (stub_dir / 'rsia_model' / 'unknown' / 'geo_utils.h').read_text()
    assert 'template <class...> struct StopWatch' in unknown
    assert 'get_or_declare(RsiaA&&...);' in unknown
    assert 'namespace motion\n' in unknown
    tu = parse_unit(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def test_a_catch_all_pointers_element_type_is_a_catch_all(tmp_path):
    # `decltype(sub_)::element_type::create_subscription(...)`: the static
    # call through what a catch-all `SharedPtr` points to
    assert_parses_clean(tmp_path, r"""
#include <rclcpp/rclcpp.hpp>
#include <geo_utils/polling.hpp>
#include <std_msgs/msg/header.hpp>
struct Selector : rclcpp::Node
{
  Selector() : Node("selector")
  {
    sub_ = decltype(sub_)::element_type::create_subscription(this, "in", 1);
    auto other = this->create_subscription<std_msgs::msg::Header>(
      "other", 1, [](std_msgs::msg::Header::ConstSharedPtr) {});
  }
  geo_utils::Poller<std_msgs::msg::Header>::SharedPtr sub_;
};
""")


def test_an_unknown_function_takes_types_and_values_as_template_arguments(
        tmp_path):
    # boost.geometry's `get<min_corner, 0>(box)` inside a constructor's
    # arguments, `get<0>(point)`, and range-v3's `to<std::vector>()`
    assert_parses_clean(tmp_path, r"""
#include <vector>
#include <boost/geometry.hpp>
#include <range/v3/range/conversion.hpp>
namespace bg = boost::geometry;
struct Point { Point(double x, double y); };
struct Box { Box(const Point & a, const Point & b); };
double area(const bg::model::box<bg::model::point_xy<double>> & hull)
{
  const Box box(
    Point(bg::get<bg::min_corner, 0>(hull), bg::get<bg::min_corner, 1>(hull)),
    Point(bg::get<bg::max_corner, 0>(hull), bg::get<1>(hull)));
  std::vector<double> xs = ranges::to<std::vector>();
  return xs.front();
}
""", repairs=[('namespace', 'boost::geometry'), ('namespace', 'ranges'),
              ('function', 'ranges::to'),
              ('namespace', 'boost::geometry::model'),
              ('template', 'boost::geometry::model::box'),
              ('template', 'boost::geometry::model::point_xy'),
              ('constant', 'boost::geometry::min_corner'),
              ('constant', 'boost::geometry::max_corner'),
              ('function', 'boost::geometry::get')])


def test_rosidls_message_trait_holds_for_messages(tmp_path):
    # a ROS 2 library's publisher helper that takes messages only
    assert_parses_clean(tmp_path, r"""
#include <map>
#include <string>
#include <type_traits>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
#include <acme_msgs/msg/float64_stamped.hpp>
class DebugPublisher
{
public:
  template <class T, std::enable_if_t<
    rosidl_generator_traits::is_message<T>::value, std::nullptr_t> = nullptr>
  void publish(const std::string & name, const T & data) {}
  template <class T, std::enable_if_t<
    !rosidl_generator_traits::is_message<T>::value, std::nullptr_t> = nullptr>
  void publish(const std::string & name, const T & value) {}
};
void report(DebugPublisher & debug, double seconds)
{
  acme_msgs::msg::Float64Stamped stamped;
  debug.publish<acme_msgs::msg::Float64Stamped>("time", stamped);
  debug.publish("value", std_msgs::msg::Float64());
  debug.publish("seconds", seconds);
  const std::string type = rosidl_generator_traits::name<acme_msgs::msg::Float64Stamped>();
  const std::string yaml = rosidl_generator_traits::to_yaml(stamped);
}
""")


def test_the_pointers_of_two_unknown_classes_are_two_types(tmp_path):
    # overloads on the pointers of two specialisations of an unknown class
    # template (PCL's point clouds), and what code does with such pointers
    assert_parses_clean(tmp_path, r"""
#include <memory>
#include <vector>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
struct Debugger
{
  void add(const pcl::PointCloud<pcl::PointXY>::Ptr & input)
  {
    pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
    xyz->points.reserve(input->points.size());
    add(xyz);
  }
  void add(const pcl::PointCloud<pcl::PointXYZ>::Ptr & input)
  {
    pcl::PointCloud<pcl::PointXYZ>::ConstPtr read_only = input;
    clouds_.push_back(pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>());
    clouds_.push_back(input);
    if (!input || input->empty() || read_only == nullptr) {
      return;
    }
  }
  std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> clouds_;
};
""")


def test_an_unknown_librarys_lower_case_name_in_a_product_is_a_value(
        tmp_path):
    # `2 * geo_utils::pi * ratio` is no declaration of a pointer; a
    # declaration of one keeps its type
    assert_parses_clean(tmp_path, r"""
#include <geo_utils/constants.hpp>
double angle(double ratio, geo_utils::handle_t * handle)
{
  geo_utils::handle_t * other = handle;
  const double theta = 2 * geo_utils::pi * ratio;
  return other ? theta : -geo_utils::pi * ratio;
}
""")


def test_a_member_one_unit_calls_with_template_arguments_is_a_template(
        tmp_path):
    package, [first, second] = write_sources(
        tmp_path,
        first='#include <cv_like/mat.hpp>\n'
              'int first(cv_like::Mat & mat) { return mat.at(0); }\n',
        second='#include <cv_like/mat.hpp>\n'
               'void second(cv_like::Mat & mat) { mat.at<unsigned char>(1, 2) = 3; }\n')
    stub_dir = tmp_path / 'stubs'
    prepare_model_arguments(package, first, stub_dir)
    # the first unit wrote `at` as a plain member; the second's use makes
    # it a member template, which takes the first's plain call too
    arguments = prepare_model_arguments(package, second, stub_dir)
    fields = (stub_dir / 'rsia_model' / 'fields.h').read_text()
    assert 'RSIA_MODEL_FIELD_TEMPLATE(at)' in fields
    for source in (first, second):
        tu = parse_unit(file=source, arguments=arguments, directory=package)
        assert cpp.parse_diagnostics(tu) == []


def test_a_repair_of_another_kind_hides_the_unknown_librarys_declaration(
        tmp_path):
    # the unknown-library header takes `geo_utils::to_msg` for an object
    # (no call on the line); the unit's repair header, force-included
    # first, declared it as a function: the header must step aside
    package, [source] = write_sources(
        tmp_path, node='#include <geo_utils/convert.hpp>\n'
                       'auto convert = geo_utils::to_msg;\n'
                       'void f() { geo_utils::to_msg(1, 2); }\n')
    stub_dir = tmp_path / 'stubs'
    arguments = prepare_model_arguments(package, source, stub_dir)
    unknown = (stub_dir / 'rsia_model' / 'unknown' / 'geo_utils.h').read_text()
    assert 'extern ::rsia_model::Any to_msg;' in unknown
    header = store.repair_header(str(stub_dir), str(source))
    store.add_repairs(header, str(source), {('function', 'geo_utils::to_msg')})
    tu = parse_unit(file=source, arguments=arguments + ['-include', header],
                    directory=package)
    assert [d for d in cpp.parse_diagnostics(tu) if 'redefinition' in d] == []


def test_a_lower_case_header_is_a_message_only_if_used_as_one():
    from colcon_rsia.frontend.cpp.model_mode.stand_ins import stand_ins_for
    # tf/tfMessage.h declares tf::tfMessage; fmt/format.h, a function
    [message] = stand_ins_for('tf/tfMessage.h', ['tf::tfMessage msg;']).values()
    assert 'kind=message' in message
    [library] = stand_ins_for(
        'fmt/format.h', ['auto text = fmt::format("{}", 1);']).values()
    assert 'kind=empty' in library
    # thrust/device_vector.h: a class template (a message takes no
    # template arguments)
    [library] = stand_ins_for(
        'thrust/device_vector.h',
        ['thrust::device_vector<float> points_;']).values()
    assert 'kind=empty' in library


@pytest.mark.parametrize('ros2', [True, False])
def test_point_cloud2_iterators_are_modelled(tmp_path, ros2):
    cloud = 'sensor_msgs::msg::PointCloud2' if ros2 else \
        'sensor_msgs::PointCloud2'
    header = 'sensor_msgs/point_cloud2_iterator.hpp' if ros2 else \
        'sensor_msgs/point_cloud2_iterator.h'
    package, [source] = write_sources(tmp_path, node=f"""
#include <{header}>
float sum(const {cloud} & cloud, {cloud} & out)
{{
  float total = 0;
  for (sensor_msgs::PointCloud2ConstIterator<float> iter_x(cloud, "x"),
       iter_y(cloud, "y");
       iter_x != iter_x.end(); ++iter_x, ++iter_y) {{
    total += *iter_x + *iter_y;
  }}
  sensor_msgs::PointCloud2Modifier modifier(out);
  modifier.setPointCloud2FieldsByString(1, "xyz");
  sensor_msgs::PointCloud2Iterator<float> out_x(out, "x");
  *out_x = total;
  // the header's helpers, called unqualified
  out.point_step = addPointField(out, "z", 1, 7, sizeOfPointField(7));
  return total;
}}
""")
    stub_dir = tmp_path / 'stubs'
    arguments = prepare_model_arguments(package, source, stub_dir)
    tu = parse_unit(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def test_a_ros2_interface_keeps_every_spelling_its_units_use(tmp_path):
    # rosidl names `uuid.hpp` after `UUID`: the first unit spells it, the
    # second includes the header without naming the type (the stand-in
    # then guesses `Uuid`); prepared in parallel, the second unit's
    # stand-in must not take the first's name away
    package, [first, second] = write_sources(
        tmp_path,
        first='#include <unique_identifier_msgs/msg/uuid.hpp>\n'
              'unique_identifier_msgs::msg::UUID id;\n'
              'unique_identifier_msgs::msg::UUID::SharedPtr ptr;\n',
        second='#include <unique_identifier_msgs/msg/uuid.hpp>\n'
               'int second() { return 0; }\n')
    stub_dir = tmp_path / 'stubs'
    arguments = prepare_model_arguments(package, first, stub_dir)
    prepare_model_arguments(package, second, stub_dir)
    tu = parse_unit(file=first, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []
    stand_in = stub_dir / 'unique_identifier_msgs' / 'msg' / 'uuid.hpp'
    assert '// declares: UUID Uuid\n' in stand_in.read_text()


def test_node_graph_queries_parameter_listing_and_time_steps(tmp_path):
    package, [source] = write_sources(tmp_path, node=r"""
#include <optional>
#include <builtin_interfaces/msg/time.hpp>
#include <rclcpp/rclcpp.hpp>

// a duration times a count (the real Duration converts to its message
// only), and a time into its message
builtin_interfaces::msg::Time later(rclcpp::Node & node, std::size_t steps)
{
  const rclcpp::Duration step(0, 100000000);
  return node.now() + step * steps;
}

// a time minus a std::chrono duration (which converts to a Duration only,
// not to a Time)
rclcpp::Time earlier(rclcpp::Node & node, int64_t count)
{
  return node.now() - std::chrono::nanoseconds(count);
}

// a time beside an optional one (which a Time does not convert from)
std::optional<rclcpp::Time> kept(
  rclcpp::Node & node, const std::optional<rclcpp::Time> & stamp)
{
  return !stamp.has_value() ? node.now() : stamp;
}

std::string first_publisher(rclcpp::Node & node)
{
  const auto names = node.list_parameters({"limits"}, 10).names;
  for (const auto & info : node.get_publishers_info_by_topic("/scan")) {
    return info.node_name() + info.node_namespace() + info.topic_type();
  }
  return node.get_subscriptions_info_by_topic("/scan").empty() ? "" : "x";
}
""")
    arguments = prepare_model_arguments(package, source, tmp_path / 'stubs')
    tu = parse_unit(file=source, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def test_constants_in_the_k_style_are_declared_for_nested_unknown_types():
    # TensorRT's `Severity::kINFO`, where Severity is a nested type of an
    # unknown class (rsia_model::Unknown): its constants are the Fields'
    constants = source_names.used_names(
        ['if (severity <= Severity::kINFO || s == Logger::CONNECTED) {}'])[1]
    assert {'kINFO', 'CONNECTED'} <= constants


def test_repaired_classes_hash_and_unknown_values_take_a_comma_initializer(
        tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <unordered_map>
#include <boost/uuid/uuid.hpp>
#include <eigen_like/core.hpp>

// a repaired class as the key of an unordered_map (its default
// constructor is deleted without a std::hash of the key)
std::unordered_map<boost::uuids::uuid, double> ages;

double run(const boost::uuids::uuid & id)
{
  ages[id] = 1.0;
  // Eigen's comma initializer on a class of the unknown library
  const eigen_like::Matrix3d m =
    (eigen_like::Matrix3d() << 1, 0, 0, 0, 1, 0, 0, 0, 1).finished();
  return ages.count(id) + m(0, 0);
}
""", {('type', 'boost::uuids::uuid')})


def test_sizes_and_c_strings_of_unknown_values_have_their_usual_types(
        tmp_path):
    package, [first, second] = write_sources(tmp_path, first=r"""
#include <vector>
#include <std_msgs/msg/string.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>
#include <eigen_like/core.hpp>

std::size_t run(const std_msgs::msg::String & text,
                const sensor_msgs::msg::PointCloud2 & cloud,
                const eigen_like::MatrixXd & matrix)
{
  // a catch-all size() would tie between vector's size and copy
  // constructors; a catch-all c_str() would not become a const char *
  std::vector<double> widths(cloud.fields.size());
  std::vector<std::vector<double>> scores(matrix.rows(), std::vector<double>(matrix.cols()));
  const char * name = text.data.c_str();
  return widths.size() + scores.size() + (name != nullptr);
}
""", second=r"""
#include <std_msgs/msg/string.hpp>

// another unit takes `size` for a value: a member for every unit
double run(std_msgs::msg::String & text) { text.size = 3; return text.size * 2; }
""")
    stub_dir = tmp_path / 'stubs'
    arguments = prepare_model_arguments(package, first, stub_dir)
    assert 'RSIA_MODEL_METHOD(size, std::size_t)' in (
        stub_dir / 'rsia_model' / 'fields.h').read_text()
    tu = parse_unit(file=first, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []
    arguments = prepare_model_arguments(package, second, stub_dir)
    fields = (stub_dir / 'rsia_model' / 'fields.h').read_text()
    assert 'RSIA_MODEL_FIELD(size)' in fields
    assert 'RSIA_MODEL_METHOD(c_str, const char *)' in fields
    tu = parse_unit(file=second, arguments=arguments, directory=package)
    assert cpp.parse_diagnostics(tu) == []


def test_classes_of_unknown_libraries_take_braces_and_iterated_elements(
        tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <vector>
#include <boost/optional.hpp>
#include <nav_msgs/msg/path.hpp>
#include <lanelet_like/lanelet.hpp>

void run(const nav_msgs::msg::Path & path, std::vector<lanelet_like::ConstLanelet> & lanelets)
{
  boost::optional<double> last;
  // `= {}` tied between the class's own assignments and those of its base
  last = {};
  last = path.poses.front();
  lanelet_like::Point2d point;
  point = {path.poses.front().pose.position.x, 2.0};
  // an element of a field binds to a reference of the class, and makes one
  // through the class's constructor: push_back(const T &) and
  // push_back(T &&) tied
  for (const auto & lanelet : path.poses) {
    lanelets.push_back(lanelet);
    const lanelet_like::ConstLanelet copy(lanelet);
  }
}
""", {('template', 'boost::optional')})


def test_catch_all_calls_take_braced_arguments(tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <vector>
#include <geometry_msgs/msg/point.hpp>
#include <grid_like/polygon.hpp>
#include <cv_like/imgproc.hpp>

void run(const geometry_msgs::msg::Point & p, grid_like::Polygon & polygon, cv_like::Mat & image)
{
  // a braced list deduces no template parameter of the catch-all calls
  polygon.addVertex({p.x, p.y});
  polygon.vertices.push_back({p.x, p.y, p.z});
  cv_like::copyMakeBorder(image, image, 0, 1, 0, 1, cv_like::BORDER_CONSTANT, {0, 0, 0});
  const auto resized = cv_like::resize<float>(image, {});
  const std::vector<double> values = grid_like::spline({1.0}, std::vector<double>{2.0}, {p.x});
  // lists of lists: a ring of points
  polygon.outer() = {{p.x, p.y}, {p.y, p.x}, {p.x, p.y}};
  polygon.outer() = {};
  const auto ring = grid_like::Polygon{{{p.x, p.y}, {p.y, p.x}}};
}
""")


def test_a_lambda_compares_catch_alls_with_a_constant_it_does_not_capture(
        tmp_path):
    assert_parses_clean(tmp_path, r"""
#include <vector>
#include <grid_like/geometry.hpp>

void run(const std::vector<int> & points, std::vector<int> & bound)
{
  // a number compared with a catch-all is read, not referred to
  constexpr double overlap = 0.01;
  const auto add = [](const std::vector<int> & ps, std::vector<int> & b) {
    for (const auto & p : ps) {
      if (b.empty() || grid_like::distance(p, b.back()) > overlap) {
        b.push_back(p);
      }
    }
    return 2 * grid_like::distance(ps.front(), b.back()) + overlap;
  };
  add(points, bound);
}
""")
