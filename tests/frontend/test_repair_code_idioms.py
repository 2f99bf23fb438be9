# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Model mode repairs: helpers of other files, aliases, macros, subdirectories."""


from colcon_rsia.frontend.cpp.model_mode import model_index
from colcon_rsia.frontend.cpp.model_mode.recovery import rules
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.package import analysis
from conftest import analyze_source
from model_sources import analyze_acme_vision
from model_sources import analyze_one_unit
from model_sources import line_reader


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
    summary = analyze_source(tmp_path, 'mapper', MAPPER_MAIN)
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
    # an enumerator of rcl's, named before anything includes it (a header
    # of an unknown library would have): the repair includes the model's
    # rclcpp.hpp, which includes generated rcl_interfaces messages the
    # unit's scan never met; without them the parse stopped at a missing
    # file. (A qualified name, `rclcpp::Duration`, is declared before the
    # first parse: test_implicit_messages.py)
    summary, unit = analyze_one_unit(tmp_path, (
        '#include <vendor_sdk/clock.hpp>\n'
        'int clock_type() {\n'
        '  return RCL_ROS_TIME;\n'
        '}\n'))
    assert [kind for _, kind, _ in unit.repairs] == ['header']
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
    summary, unit = analyze_one_unit(tmp_path, (
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
    summary, unit = analyze_one_unit(tmp_path, (
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
    summary, unit = analyze_one_unit(tmp_path, (
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
    lines = line_reader(
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
    lines = line_reader('  LOG_FAILURE(code);\n  next(code);')
    diagnostics = [("use of undeclared identifier 'logging'", 'a.cpp', 1, 3)]
    assert rules.repairs_from_diagnostics(diagnostics, lines) == {
        ('namespace', 'logging')}


def test_point_cloud_filters_cuda_calls_and_eigen_containers_parse(tmp_path):
    # what autoware's NDT and lidar packages write with PCL, Eigen and
    # CUDA, none of them in the model: traits of a class template, its
    # pointer types, an allocator, an index type, static assertions on a
    # point type's layout, a macro's call over several lines, and a time
    # passed as a message before the message's header is included
    summary, unit = analyze_one_unit(tmp_path, (
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
    summary, unit = analyze_one_unit(tmp_path, (
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
    lines = line_reader('PYBIND11_MODULE(acme_tuner, m)\n{')
    diagnostics = [('expected unqualified-id', 'a.cpp', 1, 1)]
    assert rules.repairs_from_diagnostics(diagnostics, lines) == {
        ('macro-function', 'PYBIND11_MODULE')}
    # without a body, still a statement-like declaration
    lines = line_reader(
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
    summary = analyze_acme_vision(package, tmp_path / 'build' / 'acme_vision')
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
    summary = analyze_acme_vision(package, tmp_path / 'build' / 'acme_vision')
    [unit] = summary.coverage.units
    assert unit.file == 'example_rule/src/rule.cpp'
    assert (unit.package_errors, unit.repair_rounds) == (0, 0), \
        summary.diagnostics


def test_a_name_that_ends_its_line_is_known_by_the_next_one():
    # `cond ? Qt::ForbiddenCursor` goes on with `: Qt::ArrowCursor`: a
    # value, as `Qt::ForbiddenCursor :` on one line would be
    lines = line_reader(
        '  setCursor(disabled ? Qt::ForbiddenCursor\n'
        '                     : Qt::ArrowCursor);')
    diagnostics = [("no member named 'ForbiddenCursor' in namespace 'Qt'",
                    'a.cpp', 1, 29)]
    assert rules.repairs_from_diagnostics(diagnostics, lines) == {
        ('constant', 'Qt::ForbiddenCursor')}
    # and a type at the end of its line stays one
    lines = line_reader('  std::unique_ptr<acme::Device>\n    device_;')
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
        diagnostics, line_reader('struct EIGEN_ALIGN16 LivoxPoint')) == {
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
    lines = line_reader(code)
    for name, line, column in (('resolution_', 4, 41), ('origin_x_', 5, 36)):
        diagnostics = [(f"use of undeclared identifier '{name}'", 'a.cpp',
                        line, column)]
        assert rules.repairs_from_diagnostics(
            diagnostics, lines, texts=[code]) == {('object', name)}
    code = 'void f()\n{\n  Cell * cell_ = find();\n  use(cell_);\n}\n'
    diagnostics = [("use of undeclared identifier 'cell_'", 'a.cpp', 4, 7)]
    assert rules.repairs_from_diagnostics(
        diagnostics, line_reader(code), texts=[code]) == set()


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
        diagnostics, line_reader(code), texts=[code]) == {
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
        diagnostics, line_reader(code), texts=[code]) == {('object', 'size_y_')}
    code = 'void f()\n{\n  std::vector<int> cells_;\n  use(cells_);\n}\n'
    diagnostics = [("use of undeclared identifier 'cells_'", 'a.cpp', 4, 7)]
    assert rules.repairs_from_diagnostics(
        diagnostics, line_reader(code), texts=[code]) == set()


def test_an_alias_of_its_namesake_declares_nothing_of_the_package():
    # the package opens a `namespace pcl` of its own (for a point type) and
    # aliases pcl's names: pcl::PointCloud is still pcl's, and missing
    declared = model_index.declared_names([
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
        line_reader('  using PointCloud = pcl::PointCloud<pcl::PointXYZ>;'),
        declared=declared) == {('template', 'pcl::PointCloud')}


def test_a_name_the_package_declares_in_another_namespace_is_repaired():
    # the package's `using Trajectory = autoware::trajectory::Trajectory<P>;`
    # inside its own `namespace autoware::planning` declares no
    # autoware::trajectory::Trajectory
    declared = model_index.declared_names([
        'namespace autoware::planning\n{\n'
        'class Module\n{\n'
        '  using Trajectory = autoware::trajectory::Trajectory<Point>;\n'
        '};\n}\n'])
    assert {'autoware', 'planning', 'Module'} <= declared
    line = line_reader(
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
        diagnostics, line_reader('autoware::planning::Module m;'),
        declared=declared) == set()
