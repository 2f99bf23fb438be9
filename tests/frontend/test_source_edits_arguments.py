# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""In-memory edits of a unit's code: arguments made of their parameter's type."""

import os

from colcon_rsia.frontend.cpp.model_mode.recovery import applied
from colcon_rsia.frontend.cpp.model_mode.recovery import edits as edit_rules
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import ADDRESS
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import AS
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import ASSIGNED
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import AUTO_POINTER
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import BINDING
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import CAST
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import CONSTEXPR
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import DYNAMIC_CAST
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import LAMBDA_RESULT
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import OPERAND
from model_sources import analyze_one_unit
from model_sources import EDITED_CODE
from model_sources import edited_text
from model_sources import edits_of


def test_an_argument_for_a_class_parameter_is_made_of_that_class():
    code = ('  return correct(params_.get(), shape, pose);\n'
            '  scale(2.0, gains(x, y));\n'
            '  Eigen::MatrixXf & m = maps[layer], n;\n'
            '  return points;\n'
            '  const Screen * screen_info = DefaultScreenOfDisplay(d);\n'
            'std::optional<Path> smooth();\n'
            'std::shared_ptr<Tracker> make();\n'
            '  return tracker;\n'
            '  return layer->getName();\n'
            '  std::unique_ptr<lanelet::Projector> projector = make(info);\n')
    params = 'const acme::Params &'
    edits = edit_rules.edits_from_notes([
        # at the argument, its parameter in a note
        ("no viable conversion from 'Any' to 'const Params'", 'a.cpp', 1, 18,
         [("passing argument to parameter 'param' here", 'h.hpp', 5, 30)]),
        # at the callee, the argument in a candidate's note
        ("no matching function for call to 'scale'", 'a.cpp', 2, 3,
         [('candidate function not viable: requires 3 arguments, but 2 were '
           'provided', 'h.hpp', 7, 8),
          ("candidate function not viable: no known conversion from 'Any' to "
           "'const Params' for 2nd argument", 'h.hpp', 8, 8)]),
        # no parameter: the class as the code names it
        # at the variable an initializer initialises
        ("no viable conversion from 'Any' to 'Eigen::MatrixXf'", 'a.cpp', 3,
         21, []),
        ("no viable conversion from returned value of type 'const Any' to "
         "function return type 'std::optional<Path>'", 'a.cpp', 4, 10, []),
        # a class a repair declared (Xlib's macro taken for one)
        ("no viable conversion from 'DefaultScreenOfDisplay' to "
         "'const Screen *'", 'a.cpp', 5, 18, []),
        # as clang spells it: not the code's `std::shared_ptr<Tracker>`;
        # an undeclared type reads `int`
        ("no viable conversion from returned value of type 'Any' to "
         "function return type 'shared_ptr<Tracker>'", 'a.cpp', 8, 10, []),
        ("no viable conversion from returned value of type 'Any' to "
         "function return type 'int'", 'a.cpp', 8, 10, []),
        # the one pointer a catch-all does not convert to
        ("no viable conversion from returned value of type 'Any' to "
         "function return type 'const char *'", 'a.cpp', 9, 10, []),
        # (moved, never copied)
        ("no viable conversion from 'Any' to "
         "'std::unique_ptr<lanelet::Projector>'", 'a.cpp', 10, 39, [])],
        lambda file: code,
        parameter_types=lambda *at, callee=None: {
            ('h.hpp', 7, 8): ['double', 'double', 'double'],
            ('h.hpp', 8, 8): ['double', params]}.get(at),
        parameter_type=lambda *at: {('h.hpp', 5, 30): params}.get(at))
    assert {name for _, name in edits} == {
        'a.cpp:1:18', 'a.cpp:2:14', 'a.cpp:3:25', 'a.cpp:4:10', 'a.cpp:5:32',
        'a.cpp:9:10', 'a.cpp:10:51'}
    text, _ = edited_text(edits, code)
    assert text == ('  return correct(::rsia_model::as<const acme::Params>'
                    '(params_.get()), shape, pose);\n'
                    '  scale(2.0, ::rsia_model::as<const acme::Params>'
                    '(gains(x, y)));\n'
                    '  Eigen::MatrixXf & m = ::rsia_model::as<Eigen::MatrixXf>'
                    '(maps[layer]), n;\n'
                    '  return ::rsia_model::as<std::optional<Path>>(points);\n'
                    '  const Screen * screen_info = ::rsia_model::as<const '
                    'Screen *>(DefaultScreenOfDisplay(d));\n'
                    'std::optional<Path> smooth();\n'
                    'std::shared_ptr<Tracker> make();\n'
                    '  return tracker;\n'
                    '  return ::rsia_model::as<const char *>'
                    '(layer->getName());\n'
                    '  std::unique_ptr<lanelet::Projector> projector = '
                    '::rsia_model::assigned_as<std::unique_ptr<'
                    'lanelet::Projector>>(make(info));\n')


def test_an_argument_for_a_lambdas_parameter_is_made_of_its_class():
    # a lambda has no declaration to read: the class as its note spells it
    code = ('  const auto ignored = [&](const LivoxPoint & p) { return p.tag; };\n'
            '  for (const auto & p : points) { if (ignored(p)) {} }\n'
            '  ignored(count);\n')
    edits = edit_rules.edits_from_notes([
        ("no matching function for call to object of type 'const (lambda at "
         "a.cpp:1:24)'", 'a.cpp', 2, 39,
         [("candidate function not viable: no known conversion from 'const "
           "Any' to 'const LivoxPoint' for 1st argument", 'a.cpp', 1, 24)]),
        # (from a real type: not the model's doing)
        ("no matching function for call to object of type 'const (lambda at "
         "a.cpp:1:24)'", 'a.cpp', 3, 3,
         [("candidate function not viable: no known conversion from 'int' "
           "to 'const LivoxPoint' for 1st argument", 'a.cpp', 1, 24)])],
        lambda file: code,
        parameter_types=lambda *at, callee=None: None,
        parameter_type=lambda *at: None)
    text, _ = edited_text(edits, code)
    assert len(edits) == 1
    assert text.split('\n')[1] == (
        '  for (const auto & p : points) { if (ignored('
        '::rsia_model::as<const LivoxPoint>(p))) {} }')


def test_a_catch_all_pushed_into_a_vector_of_c_strings_is_made_one():
    # a C string is the one pointer a catch-all does not convert to; the
    # note names it through the vector's alias
    code = '  names.push_back(PyBytes_AS_STRING(bytes));\n'
    note = ('candidate function not viable: no known conversion from '
            "'::rsia_model::Any' to 'const value_type' (aka 'char *const') "
            'for 1st argument')
    edits = edit_rules.edits_from_notes(
        [("no matching member function for call to 'push_back'", 'a.cpp',
          1, 9, [(note, 'stl_vector.h', 1276, 7)])],
        lambda file: code,
        parameter_types=lambda *at, callee=None: [
            'const type-parameter-0-0 &'],
        parameter_type=lambda *at: None)
    text, _ = edited_text(edits, code)
    assert text == ('  names.push_back(::rsia_model::as<char *>('
                    'PyBytes_AS_STRING(bytes)));\n')


def test_a_constant_passed_for_a_string_is_made_one():
    # a message's constant the model made an int (bond's parameter names
    # are strings); clang's note gives the parameter's type with its alias
    code = '  declare_parameter(bond::msg::Constants::TIMEOUT_PARAM, true);\n'
    note = ("candidate function not viable: no known conversion from 'const "
            "int' to 'const std::string' (aka 'const basic_string<char>') "
            'for 1st argument')
    edits = edit_rules.edits_from_notes(
        [("no matching member function for call to 'declare_parameter'",
          'a.cpp', 1, 3, [(note, 'node.hpp', 131, 34)])],
        lambda file: code,
        parameter_types=lambda *at, callee=None: {('node.hpp', 131, 34): [
            'const std::basic_string<char> &', 'bool']}.get(at),
        parameter_type=lambda *at: None)
    text, _ = edited_text(edits, code)
    assert text == (
        '  declare_parameter(::rsia_model::as<const std::basic_string<char>>'
        '(bond::msg::Constants::TIMEOUT_PARAM), true);\n')


def test_a_pointer_to_a_derived_class_of_an_unknown_library_converts():
    # the model's classes of ceres and Qt know no base classes
    code = ('  return new ceres::AutoDiffParam<Angle, 1, 1>;\n'
            '  group->addButton(button);\n'
            '  ceres::Param * p = make();\n'
            '  unsigned char * data = bytes();\n'
            '  std::unique_ptr<nvinfer1::IInt8Calibrator> c;\n'
            '  c.reset(new Int8EntropyCalibrator(stream));\n')
    message = ("cannot initialize {} of type '{}' with an {} of type '{}'")
    edits = edits_of([
          (message.format('return object', 'ceres::Param *', 'rvalue',
                          'ceres::AutoDiffParam<Angle, 1, 1> *'), 1, 10),
          (message.format('a parameter', 'QAbstractButton *', 'lvalue',
                          'CustomButton *') + " (aka 'acme::CustomButton *')",
           2, 20),  # (no edit: the code does not name the class wanted)
          (message.format('a variable', 'ceres::Param *', 'rvalue',
                          'Other *'), 3, 18),
          # a pointer of C++'s own types: not a class the code names
          (message.format('a variable', 'unsigned char *', 'rvalue',
                          'Any *'), 4, 19),
          # the type wanted through an alias of the class template
          ("cannot initialize a parameter of type 'pointer' (aka "
           "'nvinfer1::IInt8Calibrator *') with an rvalue of type "
           "'Int8EntropyCalibrator *'", 6, 11)], code)
    assert len(edits) == 3
    text, _ = edited_text(edits, code)
    assert text.split('\n')[5] == (
        '  c.reset(::rsia_model::as<nvinfer1::IInt8Calibrator *>('
        'new Int8EntropyCalibrator(stream)));')
    assert text.split('\n')[0] == (
        '  return ::rsia_model::as<ceres::Param *>('
        'new ceres::AutoDiffParam<Angle, 1, 1>);')
    assert text.split('\n')[2] == \
        '  ceres::Param * p = ::rsia_model::as<ceres::Param *>(make());'


def test_an_argument_of_a_new_class_is_made_that_class():
    # clang reports `new Handle(any)` at the class
    code = '  HandlePtr rt_goal(new Handle(gh));\n'
    edits = edit_rules.edits_from_notes(
        [("no viable conversion from 'Any' to 'Handle'", 'a.cpp', 1, 25, [])],
        lambda file: code, parameter_types=lambda *at, callee=None: None,
        parameter_type=lambda *at: None)
    text, _ = edited_text(edits, code)
    assert text == \
        '  HandlePtr rt_goal(new Handle(::rsia_model::as<Handle>(gh)));\n'


def test_a_catch_all_argument_takes_the_type_its_template_deduces():
    # `template <class T> void push(T &, const T &)` given a vector and a
    # catch-all: the catch-all is made the vector
    code = ('  pushUniqueVector(next_lanes,\n'
            '                   from_prev);\n'
            '  merge(any, std::vector<int>{});\n')
    note = ('candidate template ignored: deduced conflicting types for '
            "parameter 'T' ({} vs. {})")
    arguments = {
        ('a.cpp', 1, 3): [(1, 20, 'std::vector<lanelet::ConstLanelet>'),
                          (2, 20, 'const rsia_model::Any')],
        ('a.cpp', 3, 3): [(3, 9, 'rsia_model::AnyValue'),
                          (3, 14, 'std::vector<int>')]}
    edits = edit_rules.edits_from_notes([
        ("no matching function for call to 'pushUniqueVector'", 'a.cpp', 1,
         3, [(note.format("'lanelet::ConstLanelets' (aka "
                          "'vector<ConstLanelet>')", "'Any'"), 'h.hpp', 4,
              6)]),
        # the catch-all deduced first
        ("no matching function for call to 'merge'", 'a.cpp', 3, 3,
         [(note.format("'AnyValue'", "'std::vector<int>' (aka "
                       "'vector<int>')"), 'h.hpp', 9, 6)])],
        lambda file: code, parameter_types=lambda *at, callee=None: None,
        parameter_type=lambda *at: None,
        call_arguments=lambda *at: arguments.get(at))
    text, _ = edited_text(edits, code)
    assert text.split('\n')[1:3] == [
        '                   ::rsia_model::as<std::vector<lanelet::'
        'ConstLanelet>>(from_prev));',
        '  merge(::rsia_model::as<std::vector<int>>(any), '
        'std::vector<int>{});']


def test_a_message_constant_or_field_beside_a_fields_catch_all_is_made_one():
    # `V at_or(const std::unordered_map<K, V> &, const K &, const V &)`
    # over a map of message fields (`AnyValue` in the model), another
    # message's field (`Any`) and a message's constant (`int`)
    code = '  out.color = at_or(colors, in.color, Out::UNKNOWN);\n'
    note = ('candidate template ignored: deduced conflicting types for '
            "parameter '{}' ('rsia_model::AnyValue' vs. '{}')")
    arguments = [(1, 21, 'const std::unordered_map<rsia_model::AnyValue, '
                  'rsia_model::AnyValue> &'),
                 (1, 29, 'rsia_model::Any'), (1, 39, 'int')]

    def edited(parameter, other):
        edits = edit_rules.edits_from_notes([
            ("no matching function for call to 'at_or'", 'a.cpp', 1, 15,
             [(note.format(parameter, other), 'a.cpp', 9, 3)])],
            lambda file: code, parameter_types=lambda *at, callee=None: None,
            parameter_type=lambda *at: None,
            call_arguments=lambda *at: arguments)
        return edited_text(edits, code)[0].split('\n')[0]
    assert edited('K', 'Any') == (
             '  out.color = at_or(colors, '
             '::rsia_model::as<::rsia_model::AnyValue>(in.color), Out::UNKNOWN);')
    assert edited('V', 'int') == (
             '  out.color = at_or(colors, in.color, '
             '::rsia_model::as<::rsia_model::AnyValue>(Out::UNKNOWN));')


def test_a_value_assigned_is_made_of_its_targets_type():
    code = ('  debug.obstacles[0] = params->polygons;\n'
            '  if (x) y = z;\n'
            '  a == b;\n'
            '  if (log) {*log = handler->result(code);}\n'
            '  loss_ = new ceres::HuberLoss(0.7);\n'
            '  std::tie(left, right) = align(left, right);\n')
    message = "no viable overloaded '='"
    edits = edit_rules.edits_from_notes(
        [(message, 'a.cpp', 1, 22, []), (message, 'a.cpp', 2, 12, []),
         (message, 'a.cpp', 3, 5, []),
         # at the value (a catch-all, which converts to no `const char *`)
         ("assigning to 'const char *' from incompatible type 'Any'",
          'a.cpp', 4, 20, []),
         # a pointer to a class of an unknown library, with no base
         ("incompatible pointer types assigning to 'ceres::LossFunction *' "
          "from 'ceres::HuberLoss *'", 'a.cpp', 5, 11, []),
         (message, 'a.cpp', 6, 25, [])],
        lambda file: code,
        parameter_types=lambda *at, callee=None: None,
        parameter_type=lambda *at: None)
    assert edits == {(ASSIGNED, 'a.cpp:1:22'), (ASSIGNED, 'a.cpp:4:18'),
                     (ASSIGNED, 'a.cpp:5:9'), (ASSIGNED, 'a.cpp:6:25')}
    text, _ = edited_text(edits, code)
    assert text.split('\n')[0] == (
        '  debug.obstacles[0] = '
        '::rsia_model::assigned_as<decltype(debug.obstacles[0])>'
        '(params->polygons);')
    assert text.split('\n')[3] == (
        '  if (log) {*log = ::rsia_model::assigned_as<decltype(*log)>'
        '(handler->result(code));}')
    assert text.split('\n')[5] == (
        '  std::tie(left, right) = ::rsia_model::assigned_as<decltype('
        'std::tie(left, right))>(align(left, right));')


def test_a_messages_string_constant_initialising_a_string_is_made_one():
    # a message's string constant is an int in the model; no declaration of
    # std::string's constructors can be read (a class template's)
    code = ': Node("selector"), current_(Scenario::EMPTY), rate_(rate)\n'
    note = ('candidate constructor not viable: no known conversion from '
            "'const int' to '{}' for 1st argument")
    edits = edit_rules.edits_from_notes([(
        "no matching constructor for initialization of 'std::string' (aka "
        "'basic_string<char>')", 'a.cpp', 1, 22,
        [(note.format('const std::allocator<char>'), 'string.h', 528, 7),
         (note.format('const basic_string<char>'), 'string.h', 540, 7)])],
        lambda file: code,
        parameter_types=lambda *at, callee=None: ['const type-parameter-0-2 &'],
        parameter_type=lambda *at: None)
    text, _ = edited_text(edits, code)
    assert text == (': Node("selector"), current_(::rsia_model::as<::std::string>'
                    '(Scenario::EMPTY)), rate_(rate)\n')


def test_an_edit_whose_code_changed_is_dropped():
    edits = {(LAMBDA_RESULT, 'a.cpp:3:26'), (CONSTEXPR, 'a.cpp:15:3')}
    changed = EDITED_CODE.replace('  constexpr double lowest', '  double lowest')
    text, _ = edited_text(edits, changed)
    assert 'double lowest = kmph2mps(10);' in text
    assert text.count('AnyValue') == 1
    # nothing left to edit: the file is read as it is
    assert applied.edited_files(
        {(CONSTEXPR, 'a.cpp:15:3')}, lambda file: changed) == {}


UNIT = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/float64.hpp>
#include <acme_geometry/units.hpp>
#include <geometry_msgs/msg/pose.hpp>
#include <geometry_msgs/msg/quaternion.hpp>
#include <map>
#include <string>
#include <vector>

struct Store
{
  void keep(std::vector<int> * indices);
  void show(const geometry_msgs::msg::Quaternion & orientation, int id = 0);
  void show(const geometry_msgs::msg::Pose & pose, int id = 0);
};
double yaw_of(const geometry_msgs::msg::Quaternion & orientation);
double yaw_of(const geometry_msgs::msg::Pose & pose);
struct Gains { double low, high; };
double corrected(const Gains & gains, double value);
template <class T> void pushUnique(T & base, const T & more);

class Limiter : public rclcpp::Node
{
public:
  static constexpr float max_angle = acme_geometry::deg2rad(40.f);
  Limiter() : Node("limiter")
  {
    pub_ = create_publisher<std_msgs::msg::Float64>("limit", 1);
    sub_ = create_subscription<std_msgs::msg::Float64>(
      "speed", 1, [this](const std_msgs::msg::Float64 & m) { onSpeed(m); });
  }

private:
  void onSpeed(const std_msgs::msg::Float64 & m)
  {
    constexpr double lowest = acme_geometry::kmph2mps(10);
    const double limit = [&]() {
      if (m.data > lowest) return acme_geometry::clamp(m.data);
      return 0.0;
    }();
    auto pick = [&] {
      if (limit > 1.0) {
        return 2.0;
      }
      return acme_geometry::clamp(limit);
    };
    const auto * row = image_.ptr<float>(0);
    const auto & [low, high] = acme_geometry::bounds(limit);
    for (const auto & [name, offset] : image_.channels()) {}
    store_.keep(&image_.indices);
    store_.show(m.orientation, 1);
    const double yaw = yaw_of(m.pose);
    const double fixed = corrected(image_.gains(), yaw);
    acme_geometry::Polygons polygons;
    std::unique_ptr<std::vector<double>> areas;
    areas = polygons;
    std::vector<int> * kept = &(image_.kept);
    const std::string label{acme_geometry::name_of(limit)};
    image_.points = {m.data, limit};
    std::vector<int> ids;
    pushUnique(ids, acme_geometry::ids_of(limit));
    std::map<long, double> starts;
    starts.erase(acme_geometry::id_of(limit));
    std::vector<size_t> sizes(acme_geometry::count(limit));
    acme_geometry::Shape * shape = image_.shape();
    auto * circle = dynamic_cast<acme_geometry::Circle *>(shape);
    const std::string tag = m.data ? "" : acme_geometry::name_of(m) + "/";
    std_msgs::msg::Float64 out =
      acme_geometry::convertTo<std_msgs::msg::Float64>(limit);
    out.data = limit + pick() + row[0] + max_angle + low + fixed;
    pub_->publish(out);
  }
  acme_geometry::Image image_;
  Store store_;
  rclcpp::Publisher<std_msgs::msg::Float64>::SharedPtr pub_;
  rclcpp::Subscription<std_msgs::msg::Float64>::SharedPtr sub_;
};
"""


def test_a_unit_parses_clean_with_its_code_edited_in_memory(tmp_path):
    summary, unit = analyze_one_unit(tmp_path, UNIT)
    assert unit.package_errors == 0, summary.diagnostics
    [node] = summary.nodes
    [publisher] = node.publishers
    assert publisher.topic == 'limit'
    assert publisher.label == 'dependent'
    # at its line in the file, which stays as it was on disk
    assert publisher.publish_sites == ['src/detector_node.cpp:71']
    source = tmp_path / 'src' / 'acme_vision' / 'src' / 'detector_node.cpp'
    assert source.read_text() == UNIT
    [header] = [os.path.join(root, name)
                for root, _, names in os.walk(tmp_path / 'build')
                for name in names if '/repair' in root and
                name.startswith('detector_node') and name.endswith('.h')]
    # the unit's repairs, each with the rule that made it
    records = store.read_records(header)
    kinds = [kind for kind, _ in records]
    assert all(rule == kind.partition(':')[0]
               for (kind, _), rule in records.items()
               if kind.startswith('edit-'))
    assert sorted(k.partition(':')[0] for k in kinds) == sorted([
        ADDRESS, ADDRESS, AS, AS, AS, ASSIGNED, AUTO_POINTER, BINDING,
        BINDING, CAST, CAST, CAST, CONSTEXPR, CONSTEXPR, DYNAMIC_CAST,
        LAMBDA_RESULT, LAMBDA_RESULT, OPERAND])
