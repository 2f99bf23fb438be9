# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""In-memory edits of a unit's code, for errors no declaration settles."""

from colcon_rsia.frontend.cpp.model_mode.recovery import applied
from colcon_rsia.frontend.cpp.model_mode.recovery import edits as edit_rules
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import ADDRESS
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import AUTO_POINTER
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import BINDING
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import CONSTEXPR
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import DYNAMIC_CAST
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import INDEX
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import LAMBDA_RESULT
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import MEMBER_POINTER
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import OPERAND
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import RANGE_REFERENCE
from colcon_rsia.frontend.cpp.model_mode.recovery.edits import REINTERPRET_CAST
from model_sources import analyze_one_unit
from model_sources import EDITED_CODE
from model_sources import edited_text
from model_sources import edits_of


MISMATCH = ("return type 'double' must match previous return type 'Any' "
            'when lambda expression has unspecified explicit return type')
MISMATCH_OF_ALIASES = (
    "return type 'Point' (aka 'Point_<std::allocator<void>>') must match "
    "previous return type 'value_type' (aka 'double') when lambda expression "
    'has unspecified explicit return type')


def test_a_lambda_with_mixed_returns_returns_a_catch_all_value():
    # the returns in line 7 (after an if-block in the lambda) and line 9
    # (a lambda without parameters, a brace in a string before it)
    edits = edits_of([(MISMATCH, 7, 5), (MISMATCH_OF_ALIASES, 9, 18)])
    assert edits == {(LAMBDA_RESULT, 'a.cpp:3:26'),
                     (LAMBDA_RESULT, 'a.cpp:9:16')}
    text, insertions = edited_text(edits)
    lines = text.split('\n')
    assert lines[2] == \
        '  const double a = [&]() -> ::rsia_model::AnyValue {'
    assert lines[8].startswith(
        '  auto b = [&] () -> ::rsia_model::AnyValue { return "}"[0]')
    # every other line as it was, and a column after an insertion maps
    # back to the file's
    assert len(lines) == len(EDITED_CODE.split('\n'))
    assert [line for i, line in enumerate(lines) if i not in (2, 8)] == \
        [line for i, line in enumerate(EDITED_CODE.split('\n')) if i not in (2, 8)]
    assert applied.disk_column(insertions, 9, 16 + 29) == 16
    assert applied.disk_column(insertions, 9, 5) == 5
    assert applied.disk_column(insertions, 3, 5) == 5


def test_a_return_outside_any_lambda_is_not_edited():
    # the return of line 12 is the function's own: no lambda around it
    assert edits_of([(MISMATCH, 12, 5)]) == set()


def test_a_pointer_auto_and_constexpr_variables_take_a_catch_all():
    edits = edits_of([
          ("variable 'row' with type 'auto *const' has incompatible "
           "initializer of type '::rsia_model::Any'", 14, 16),
          ("constexpr variable 'lowest' must be initialized by a constant "
           'expression', 15, 20),
          ("constexpr variable 'max_angle' must be initialized by a "
           'constant expression', 19, 26)])
    assert edits == {(AUTO_POINTER, 'a.cpp:14:8'), (CONSTEXPR, 'a.cpp:15:3'),
                     (CONSTEXPR, 'a.cpp:19:10')}
    text, insertions = edited_text(edits)
    lines = text.split('\n')
    assert lines[13] == '  auto   const row = img.ptr<float>(i);'
    assert lines[14] == '  static const double lowest = kmph2mps(10);'
    # a static member keeps its initializer as an inline variable
    assert lines[18] == '  static inline    float max_angle = deg2rad(40.f);'
    # (three more characters: columns after them map back)
    assert applied.disk_column(insertions, 15, 23) == 20
    assert set(insertions) == {15}


def test_casts_of_repaired_classes_and_catch_alls_are_made_to_work():
    code = ('  auto conv = dynamic_cast<nvinfer1::IConvolutionLayer *>(layer);\n'
            '  auto & c = dynamic_cast<const Conv &>(*layer); f(conv, c);\n'
            '  return reinterpret_cast<const char *>(blob.data());\n'
            '  auto p = reinterpret_cast<const float *>(&value);\n')
    message = "'nvinfer1::ILayer' is not polymorphic"
    any_to = "reinterpret_cast from '{}' to '{}' is not allowed"
    # clang reports at the keyword or at the operand
    edits = edits_of([
          (message, 1, 15), (message, 2, 41),
          (any_to.format('Any', 'const char *'), 3, 10),
          # (a real value: not the model's doing)
          (any_to.format('std::string', 'const float *'), 4, 12)], code)
    assert edits == {(DYNAMIC_CAST, 'a.cpp:1:15'),
                     (DYNAMIC_CAST, 'a.cpp:2:14'),
                     (REINTERPRET_CAST, 'a.cpp:3:10')}
    text, insertions = edited_text(edits, code)
    assert text.split('\n')[:3] == [
        '  auto conv = reinterpret_cast<nvinfer1::IConvolutionLayer *>'
        '(layer);',
        '  auto & c = reinterpret_cast<const Conv &>(*layer); f(conv, c);',
        '  return ::rsia_model::as<const char *>(blob.data());']
    assert applied.disk_column(insertions, 2, 59) == 55


def test_structured_bindings_of_a_catch_all_get_as_many_values():
    code = (
        'void f(const Any & any)\n'
        '{\n'
        '  const auto & [id, path] = any.at(0) == 1 ? any : any;\n'
        '  for (auto && [a, b, c] : any) {}\n'
        '  auto [x, y]{any};\n'
        '}\n')
    edits = edits_of([
          ("type 'const Any' decomposes into 0 elements, but 2 names were "
           'provided', 3, 16),
          ("type 'const AnyElement' decomposes into 0 elements, but 3 names "
           'were provided', 4, 16),
          ("type 'Any' decomposes into 0 elements, but 2 names were "
           'provided', 5, 8)], code)
    assert edits == {(BINDING, 'a.cpp:3:16'), (BINDING, 'a.cpp:4:16'),
                     (BINDING, 'a.cpp:5:8')}
    text, insertions = edited_text(edits, code)
    assert text.split('\n')[2:5] == [
        '  const auto & [id, path] = ::rsia_model::Bound<2>() <<=  '
        'any.at(0) == 1 ? any : any;',
        '  for (auto && [a, b, c] : ::rsia_model::BoundEach<3>() <<=  any) {}',
        '  auto [x, y]{ ::rsia_model::Bound<2>() <<= any};']
    assert applied.disk_column(insertions, 4, 62) == 28


def test_the_address_of_a_catch_all_is_the_catch_all():
    code = ('  fill(&(cell.layout), &out);\n'
            '  unsigned char * data = &msg.data[0];\n')
    message = ("cannot initialize a {} of type '{}' with an rvalue of type "
               "'{}'")
    edits = edits_of([
          (message.format('parameter', "std::string *' (aka 'basic_string<char>"
                          ' *', 'Any *'), 1, 8),
          (message.format('variable', 'unsigned char *',
                          '::rsia_model::Any *'), 2, 19)], code)
    assert edits == {(ADDRESS, 'a.cpp:1:8'), (ADDRESS, 'a.cpp:2:26')}
    text, _ = edited_text(edits, code)
    assert text == ('  fill( (cell.layout), &out);\n'
                    '  unsigned char * data =  msg.data[0];\n')


def test_a_range_for_reference_to_a_catch_alls_element_is_a_copy():
    code = ('  for (lanelet::LineString3d & line : map->lineStringLayer) {}\n'
            '  for (Point & p : points) {}\n'
            '  Point & q = points.front();\n')
    message = "no viable conversion from 'AnyElement' to '{}'"
    errors = [(message.format('lanelet::LineString3d'), 1, 32),
              (message.format('Point'), 2, 16),
              # (no range-for)
              (message.format('Point'), 3, 11)]
    edits = edits_of(errors, code)
    assert edits == {(RANGE_REFERENCE, 'a.cpp:1:30'),
                     (RANGE_REFERENCE, 'a.cpp:2:14')}
    text, _ = edited_text(edits, code)
    assert text.split('\n')[:2] == [
        '  for (lanelet::LineString3d   line : map->lineStringLayer) {}',
        '  for (Point   p : points) {}']
    # no other edit there: the range is no value of the class
    assert edit_rules.edits_from_notes(
        [(m, 'a.cpp', line, column, []) for m, line, column in errors[:2]],
        lambda file: code, parameter_types=lambda *at, callee=None: None,
        parameter_type=lambda *at: None) == set()


def test_a_pointers_subscript_by_a_catch_all_is_made_a_number():
    # a message's field offsets (catch-alls) index a byte pointer
    code = ('  float x = *reinterpret_cast<const float *>(&data[row + off[0]]);\n'
            '  auto y = values[ i ];\n')
    message = 'array subscript is not an integer'
    edits = edits_of([(message, 1, 51), (message, 2, 18),
                      (message, 2, 12)], code)  # (no `[` at the last)
    assert edits == {(INDEX, 'a.cpp:1:51'), (INDEX, 'a.cpp:2:18')}
    text, _ = edited_text(edits, code)
    assert text.split('\n')[:2] == [
        '  float x = *reinterpret_cast<const float *>('
        '&data[::rsia_model::as<long>(row + off[0])]);',
        '  auto y = values[::rsia_model::as<long>( i )];']


def test_a_member_pointer_to_a_repaired_classs_member_is_a_pointer():
    # `&RouteHandler::getLeftLanelets` of a repaired class is the address
    # of a static catch-all: it is called through the pointer alone
    code = ('  auto lanes = (route_handler.*getOpposite)(lane);\n'
            '  auto more = (self->handler_->*next)(lane);\n')
    message = ('right hand operand to {} has non-pointer-to-member type '
               "'::rsia_model::Any *'")
    edits = edits_of([(message.format('.*'), 1, 30),
                      (message.format('->*'), 2, 30)], code)
    assert edits == {(MEMBER_POINTER, 'a.cpp:1:30'),
                     (MEMBER_POINTER, 'a.cpp:2:30')}
    text, _ = edited_text(edits, code)
    assert text.split('\n')[:2] == [
        '  auto lanes = (' + ' ' * len('route_handler.') + '*getOpposite)'
        '(lane);',
        '  auto more = (' + ' ' * len('self->handler_->') + '*next)(lane);']


def test_the_address_of_a_catch_all_passed_to_an_overload_is_dropped():
    # a standard container's member: the parameter is read from the note
    code = '  paths.push_back(&object.paths.at(i)); keep(&count);\n'
    note = ("candidate function not viable: no known conversion from '{}' "
            "to 'const PredictedPath *const' for 1st argument")
    edits = edit_rules.edits_from_notes([
        ("no matching member function for call to 'push_back'",
         'a.cpp', 1, 9, [(note.format('rsia_model::AnyElement *'),
                          'stl_list.h', 1200, 7)]),
        # (a real pointer: not the model's doing)
        ("no matching function for call to 'keep'", 'a.cpp', 1, 42,
         [(note.format('int *'), 'a.hpp', 3, 6)])],
        lambda file: code,
        parameter_types=lambda *at, callee=None: None,
        parameter_type=lambda *at: None)
    assert edits == {(ADDRESS, 'a.cpp:1:19')}
    text, _ = edited_text(edits, code)
    assert text == '  paths.push_back( object.paths.at(i)); keep(&count);\n'


def test_a_conditionals_operand_takes_the_type_of_the_other():
    code = ('  auto p = unit->path().empty() ? "" : unit->path() + " ";\n'
            '  s = "a" + (ok ? names[i] : "/" "b") + f(x ? y : z);\n'
            '  t = ok ? std::string("x") : n::label("?:");\n'
            '  auto cloud = use ? sub.take() : nullptr;\n'
            '  const auto l = ok ? status.level : Status::OK;\n'
            '  const auto m = ok ? status.level : Limits<int, 2>::MAX;\n'
            '  name = stopped ? Scenario::PARKING : current;\n')
    message = "incompatible operand types ('{}' and '{}')"
    edits = edits_of([(message.format('const char[1]', 'Any'), 1, 33),
                      (message.format('AnyElement', 'const char[3]'), 2, 17),
                      # a catch-all beside a class the code names
                      (message.format('std::string', 'Any'), 3, 10),
                      ("non-pointer operand type 'Any' incompatible with "
                       'nullptr', 4, 20),
                      ("conditional expression is ambiguous; 'DiagnosticLevel' "
                       "(aka 'rsia_model::AnyValue') can be converted to "
                       "'const int' and vice versa", 5, 21),
                      # (template arguments end no operand)
                      ("conditional expression is ambiguous; 'AnyValue' can "
                       "be converted to 'const int' and vice versa", 6, 21),
                      # a message's string constant is an int in the model
                      ("incompatible operand types ('const int' and "
                       "'std::string' (aka 'basic_string<char>'))", 7, 18)],
                     code)
    string = 'edit-operand:{}:%3A%3Astd%3A%3Astring'
    value = 'edit-operand:{}:%3A%3Arsia_model%3A%3AAnyValue'
    assert edits == {(string.format(2), 'a.cpp:1:33'),
                     (string.format(3), 'a.cpp:2:17'),
                     ('edit-operand:3:std%3A%3Astring', 'a.cpp:3:10'),
                     (value.format(3), 'a.cpp:4:20'),
                     (value.format(3), 'a.cpp:5:21'),
                     (value.format(3), 'a.cpp:6:21'),
                     ('edit-operand:2:%3A%3Astd%3A%3Abasic_string%3Cchar%3E',
                      'a.cpp:7:18')}
    assert {kind.partition(':')[0] for kind, _ in edits} == {OPERAND}
    # a literal's edit where the operand is no literal changes nothing
    edits.add((string.format(2), 'a.cpp:3:10'))
    text, _ = edited_text(edits, code)
    assert text.split('\n') == [
        '  auto p = unit->path().empty() ? ::rsia_model::as<::std::string>( "" ): '
        'unit->path() + " ";',
        '  s = "a" + (ok ? names[i] : ::rsia_model::as<::std::string>( "/" "b")) '
        '+ f(x ? y : z);',
        '  t = ok ? std::string("x") : ::rsia_model::as<std::string>( '
        'n::label("?:"));',
        '  auto cloud = use ? sub.take() : ::rsia_model::as<::rsia_model::AnyValue>'
        '( nullptr);',
        '  const auto l = ok ? status.level : ::rsia_model::as<::rsia_model::'
        'AnyValue>( Status::OK);',
        '  const auto m = ok ? status.level : ::rsia_model::as<::rsia_model::'
        'AnyValue>( Limits<int, 2>::MAX);',
        '  name = stopped ? ::rsia_model::as<::std::basic_string<char>>( '
        'Scenario::PARKING ): current;', '']


def test_an_ambiguous_call_takes_its_first_candidate_that_is_no_template():
    code = ('  if (is_timeout(msg.header.stamp, 1.0) ||\n'
            '      checker.willLeave({lane}, path)) {}\n'
            '  fill({lane}, path);\n')
    time = 'const builtin_interfaces::msg::Time_<std::allocator<void> > &'
    types = {('h.hpp', 3, 6): None,  # a template
             ('h.hpp', 4, 6): [time, 'double'],
             ('h.hpp', 8, 6): ['(lambda at h.hpp:8:20)', 'const Path &'],
             ('h.hpp', 9, 6): ['const std::vector<int> &', 'const Path &'],
             ('h.hpp', 12, 6): ['std::vector<int> &', 'const Path &']}
    candidate = 'candidate function'
    edits = edit_rules.edits_from_notes([
        ("call to 'is_timeout' is ambiguous", 'a.cpp', 1, 7,
         [(candidate, 'h.hpp', 3, 6), (candidate, 'h.hpp', 4, 6)]),
        ("call to member function 'willLeave' is ambiguous", 'a.cpp', 2, 15,
         [(candidate, 'h.hpp', 8, 6), (candidate, 'h.hpp', 9, 6)]),
        ("no matching function for call to 'f'", 'a.cpp', 1, 7,
         [(candidate, 'h.hpp', 9, 6)]),
        ("call to 'fill' is ambiguous", 'a.cpp', 3, 3,
         [(candidate, 'h.hpp', 12, 6)])], lambda file: code,
        parameter_types=lambda *at, callee=None: types.get(at),
        parameter_type=lambda *at: None)
    assert {name for _, name in edits} == {'a.cpp:1:7', 'a.cpp:2:15',
                                           'a.cpp:3:3'}
    text, insertions = edited_text(edits, code)
    assert text.split('\n')[:3] == [
        f'  if (is_timeout(::rsia_model::as<{time}>(msg.header.stamp), '
        '::rsia_model::as<double>(1.0)) ||',
        # a braced argument is made a temporary of the class
        '      checker.willLeave(std::vector<int>{lane}, '
        '::rsia_model::as<const Path &>(path))) {}',
        # (not for a reference to a class to change: no temporary binds)
        '  fill({lane}, ::rsia_model::as<const Path &>(path));']
    assert applied.disk_column(insertions, 2, 80) == 33


def test_a_literal_argument_keeps_its_place_among_the_casts():
    # `pushPoseMarker(p.at(i), "angle", 0)` over a message's catch-all
    # field: the cast for the string goes to the literal (blank in the
    # masked code), not to the number after it
    code = '  debug->pushPoseMarker(p.at(i), "angle", 0);\n  f("a");\n'
    candidate = 'candidate function'
    types = {('h.hpp', 3, 6): ['const Point &', 'const std::string &', 'int'],
             ('h.hpp', 5, 6): ['const std::string &']}
    edits = edit_rules.edits_from_notes([
        ("call to member function 'pushPoseMarker' is ambiguous", 'a.cpp',
         1, 10, [(candidate, 'h.hpp', 3, 6)]),
        ("call to 'f' is ambiguous", 'a.cpp', 2, 3,
         [(candidate, 'h.hpp', 5, 6)])], lambda file: code,
        parameter_types=lambda *at, callee=None: types.get(at),
        parameter_type=lambda *at: None)
    text, _ = edited_text(edits, code)
    assert text.split('\n')[:2] == [
        '  debug->pushPoseMarker(::rsia_model::as<const Point &>(p.at(i)),'
        '::rsia_model::as<const std::string &>( "angle"), '
        '::rsia_model::as<int>(0));',
        '  f(::rsia_model::as<const std::string &>("a"));']


def test_math_functions_of_catch_alls_take_their_first_overload(tmp_path):
    # <cmath>'s overloads are declared in the precompiled model, where
    # clang finds no declaration by its place: they are found among those
    # the call names (an rviz property's value and a message's field are
    # catch-alls, for float, double and long double alike)
    summary, unit = analyze_one_unit(tmp_path, (
        '#include <cmath>\n'
        '#include <rclcpp/rclcpp.hpp>\n'
        '#include <acme_props/float_property.hpp>\n'
        'float wave(float range, acme_props::FloatProperty * property)\n'
        '{\n'
        '  range = std::fmod(range, property->getFloat());\n'
        '  for (auto & r : property->ranges) {\n'
        '    if (std::isinf(r)) { return 1.0f; }\n'
        '  }\n'
        '  return range;\n'
        '}\n'))
    assert unit.package_errors == 0, summary.diagnostics


def test_an_ambiguous_constructor_of_one_argument_copies_the_class():
    # the candidates are a class template's: none names its parameters
    code = ('  vindices.reset(new std::vector<int>(indices->indices));\n'
            '  std::vector<size_t> sizes(cluster.width * cluster.height);\n'
            '  std::vector<size_t> filled(cluster.width, 0);\n'
            '  outer.push_back(Point2d(point));\n')
    candidate = ('candidate constructor', 'stl_vector.h', 512, 7)
    edits = edit_rules.edits_from_notes([
        ("call to constructor of 'std::vector<int>' is ambiguous",
         'a.cpp', 1, 22, [candidate]),
        ("call to constructor of 'std::vector<size_t>' (aka 'vector<unsigned "
         "long>') is ambiguous", 'a.cpp', 2, 23, [candidate]),
        # two arguments: which constructor is meant is not known
        ("call to constructor of 'std::vector<size_t>' (aka 'vector<unsigned "
         "long>') is ambiguous", 'a.cpp', 3, 23, [candidate]),
        # a functional cast of a catch-all: the same
        ("ambiguous conversion for functional-style cast from 'const "
         "AnyElement' to 'Point2d' (aka 'acme::Vector2d')", 'a.cpp', 4, 19,
         [candidate])],
        lambda file: code,
        parameter_types=lambda *at, callee=None: None,
        parameter_type=lambda *at: None)
    text, _ = edited_text(edits, code)
    assert text.split('\n')[:4] == [
        '  vindices.reset(new std::vector<int>('
        '::rsia_model::as<std::vector<int>>(indices->indices)));',
        '  std::vector<size_t> sizes('
        '::rsia_model::as<std::vector<size_t>>(cluster.width * '
        'cluster.height));',
        '  std::vector<size_t> filled(cluster.width, 0);',
        '  outer.push_back(Point2d(::rsia_model::as<Point2d>(point)));']
