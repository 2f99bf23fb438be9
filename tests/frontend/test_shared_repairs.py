# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""What the model mode learns in one unit, the units parsed later start with.

A header of an unmodelled library is included by the units of many
packages; the declarations one unit's repairs made for it are offered to
every later unit of the workspace, so that those parse cleanly at once.
Names the workspace's own code declares are never offered that way: a unit
of another package may include the real declaration.
"""

from pathlib import Path

from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.package import analysis
from colcon_rsia.package.build_paths import workspace_repairs_file
import pytest

# a library no model header and no package of the workspace provides, its
# header included by some other header
USES_UNKNOWN_LIBRARY = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class {name} : public rclcpp::Node
{{
public:
  {name}() : Node("{name}")
  {{
    // a namespace and a macro that no included header mentions: only the
    // parse's errors show them
    zoom_ = optics::calibrated_zoom(2);
#if OPTICS_VERSION_GTE(1, 2, 0)
    zoom_ *= 2;
#endif
    publisher_ = create_publisher<std_msgs::msg::String>("{topic}", 10);
  }}

private:
  double zoom_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr publisher_;
}};

int main(int argc, char ** argv)
{{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<{name}>());
  return 0;
}}
"""


def _package(root, name, topic):
    package = root / 'src' / name
    (package / 'src').mkdir(parents=True)
    (package / 'src' / f'{name}.cpp').write_text(
        USES_UNKNOWN_LIBRARY.format(name=name, topic=topic))
    (package / 'CMakeLists.txt').write_text(
        f'cmake_minimum_required(VERSION 3.8)\nproject({name})\n'
        f'add_executable({name} src/{name}.cpp)\n')
    return package


def _analyze(root, package, workspace, repair=analysis.REPAIR_ALWAYS):
    return analysis.analyze_package(
        name=package.name, path=str(package),
        build_base=str(root / 'build' / package.name), jobs=1,
        header_mode='model', workspace_package_dirs=[str(p) for p in workspace],
        repair=repair)


@pytest.fixture(scope='module')
def two_packages(tmp_path_factory):
    root = tmp_path_factory.mktemp('shared_repairs')
    first = _package(root, 'viewer', 'view')
    second = _package(root, 'recorder', 'record')
    return root, first, second


def test_a_second_package_starts_with_what_the_first_needed(two_packages):
    root, first, second = two_packages
    workspace = [first, second]
    [unit] = _analyze(root, first, workspace).coverage.units
    # optics::calibrated_zoom and OPTICS_VERSION_GTE are nowhere: repaired
    assert unit.repair_rounds >= 1
    assert unit.package_errors == 0

    summary = _analyze(root, second, workspace)
    [unit] = summary.coverage.units
    assert (unit.package_errors, unit.repair_rounds) == (0, 0)
    # the repairs it started with say where they came from
    assert unit.repairs
    assert {rule for rule, _, _ in unit.repairs} == {store.SEEDED}
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['record']


def test_a_unit_not_worth_repairing_still_teaches_the_later_ones(tmp_path):
    # the default policy: the first unit's publisher has its fact despite
    # the errors, so the unit is not repaired; what they show missing it
    # offers its package, and, once the package's units are parsed, it is
    # parsed once more seeded with that (recovery.reseed): one round
    first = _package(tmp_path, 'viewer', 'view')
    second = _package(tmp_path, 'recorder', 'record')
    workspace = [first, second]
    [unit] = _analyze(tmp_path, first, workspace,
                      analysis.REPAIR_WHEN_IT_PAYS).coverage.units
    assert (unit.package_errors, unit.repair_rounds) == (0, 1)

    # what its errors showed missing, the next package's unit starts with
    summary = _analyze(tmp_path, second, workspace,
                       analysis.REPAIR_WHEN_IT_PAYS)
    [unit] = summary.coverage.units
    assert (unit.package_errors, unit.repair_rounds) == (0, 0)
    assert {rule for rule, _, _ in unit.repairs} == {store.SEEDED}
    [node] = summary.nodes
    assert [p.topic for p in node.publishers] == ['record']


def test_names_the_workspace_declares_are_not_offered_to_it(tmp_path):
    header = tmp_path / 'pkg' / 'rsia_model' / 'repair' / 'unit.h'
    header.parent.mkdir(parents=True)
    workspace = store.WorkspaceRepairs(
        # (the names the workspace's code declares: namespaces and classes)
        str(tmp_path / 'workspace.json'), {'gizmo', 'Lens'})
    store.share_repairs(str(header), {
        ('type', 'gizmo::Lens'), ('type', 'gizmo::Focus'),
        # a stand-in header, written into this package's stub directory
        # only, and a standard header, found from everywhere
        ('header', 'gizmo_msgs/msg/lens.hpp'), ('std-header', 'optional')},
        workspace)

    other = tmp_path / 'other' / 'rsia_model' / 'repair' / 'unit.h'
    other.parent.mkdir(parents=True)
    store.ensure_repair_header(str(other), 'src/other.cpp')
    store.seed_repairs(str(other), 'src/other.cpp', set(), workspace)
    seeded = store.read_repairs(str(other))
    assert ('type', 'gizmo::Focus') in seeded
    assert ('type', 'gizmo::Lens') not in seeded
    assert ('std-header', 'optional') in seeded
    assert ('header', 'gizmo_msgs/msg/lens.hpp') not in seeded
    # its own package's units are offered everything shareable
    same = header.parent / 'second.h'
    store.ensure_repair_header(str(same), 'src/second.cpp')
    store.seed_repairs(str(same), 'src/second.cpp', set())
    assert {('type', 'gizmo::Lens'), ('header', 'gizmo_msgs/msg/lens.hpp')} \
        <= store.read_repairs(str(same))


def test_the_workspace_file_lies_beside_the_packages_outputs(tmp_path):
    path = Path(workspace_repairs_file(str(tmp_path / 'build' / 'viewer')))
    assert path.is_relative_to(tmp_path / 'build')
    assert not path.is_relative_to(tmp_path / 'build' / 'viewer')


# a package header whose call the catch-all types make ambiguous: any unit
# that includes it meets the same error at the same place
CONVERT_HEADER = """\
#pragma once
#include <string>
#include <corp_geometry/state.hpp>

namespace conv
{
inline void copy(const corp_geometry::Pose & in, std::string & out) {}
inline void copy(const corp_geometry::Twist & in, std::string & out) {}

inline std::string describe(const corp_geometry::State & state)
{
  std::string text;
  copy(state.pose, text);
  return text;
}
}  // namespace conv
"""
CONVERT_USER = """\
#include "conv/convert.hpp"

std::string {name}(const corp_geometry::State & state)
{{
  return conv::describe(state);
}}
"""


def test_an_edit_in_a_header_is_shared_with_the_units_including_it(tmp_path):
    package = tmp_path / 'src' / 'conv'
    (package / 'include' / 'conv').mkdir(parents=True)
    (package / 'include' / 'conv' / 'convert.hpp').write_text(CONVERT_HEADER)
    (package / 'src').mkdir()
    for name in ('first', 'second'):
        (package / 'src' / f'{name}.cpp').write_text(
            CONVERT_USER.format(name=name))
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(conv)\n'
        'include_directories(include)\n'
        'add_library(conv src/first.cpp src/second.cpp)\n')
    units = _analyze(tmp_path, package, [package]).coverage.units
    first, second = sorted(units, key=lambda u: u.file)
    assert first.repair_rounds >= 1
    assert first.package_errors == 0
    # the second starts with the first one's edit of the header
    assert (second.package_errors, second.repair_rounds) == (0, 0)
    # (a cast of the arguments to the first candidate's parameters)
    assert [(rule, kind.partition(':')[0]) for rule, kind, _
            in second.repairs if kind.startswith('edit')] == [
        (store.SEEDED, 'edit-cast')]


# a package whose two programs include one header that uses a library's
# logging macro, unknown before a parse shows it missing; the third's own
# error is one no rule answers
NOTE_HEADER = """\
#pragma once
#include <string>
#include <vendor/log.h>

inline void note(const std::string & what)
{
  VENDOR_LOG_INFO("note: %s", what.c_str());
}
"""

RELAY = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
#include "relay/note.hpp"

ros::Publisher pub;

void forward(const std_msgs::String::ConstPtr & msg)
{{
  note(msg->data);
  pub.publish(*msg);
}}

int main(int argc, char ** argv)
{{
  ros::init(argc, argv, "{name}");
  ros::NodeHandle nh;
  pub = nh.advertise<std_msgs::String>("{name}_out", 1);
  ros::Subscriber sub = nh.subscribe("{name}_in", 1, forward);
  {extra}
  ros::spin();
}}
"""


def test_a_unit_parsed_before_its_package_learnt_is_parsed_once_more(
        tmp_path):
    package = tmp_path / 'relay'
    (package / 'include' / 'relay').mkdir(parents=True)
    (package / 'include' / 'relay' / 'note.hpp').write_text(NOTE_HEADER)
    (package / 'src').mkdir()
    for name, extra in (('first', ''), ('second', ''),
                        ('third', 'int broken = ;')):
        (package / 'src' / f'{name}.cpp').write_text(
            RELAY.format(name=name, extra=extra))
    (package / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.8)\nproject(relay)\n' + ''.join(
            f'add_executable({n} src/{n}.cpp)\n'
            for n in ('first', 'second', 'third')))
    # one unit at a time, in order: the first meets the macro before any
    # unit of its package has shown it missing
    summary = analysis.analyze_package(
        name='relay', path=str(package), build_base=str(tmp_path / 'b'),
        jobs=1, header_mode='model', workspace_package_dirs=[str(package)],
        repair=analysis.REPAIR_WHEN_IT_PAYS)
    units = {u.file: u for u in summary.coverage.units}
    # before: the first kept the error in note.hpp, that its own parse
    # showed missing and the second started without
    assert (units['src/first.cpp'].package_errors,
            units['src/first.cpp'].repair_rounds) == (0, 1)
    assert (units['src/second.cpp'].package_errors,
            units['src/second.cpp'].repair_rounds) == (0, 0)
    # a syntax error: nothing the package learnt answers it,
    # so one parse only
    assert (units['src/third.cpp'].package_errors,
            units['src/third.cpp'].repair_rounds) == (1, 0)
    assert sorted(p.topic for n in summary.nodes for p in n.publishers) == [
        'first_out', 'second_out', 'third_out']
