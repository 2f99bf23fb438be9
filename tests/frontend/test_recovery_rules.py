# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The recovery's rule table: each rule's worked examples, and its limits.

One test per rule and example is generated from the table itself
(recovery/rules.py): the example's line and clang's message go through
the rules, and the rule must be the one that answers, with the repairs the
example says. The other tests hold for the whole table: no rule names a
library, and what the repairs declare compiles.
"""

import glob
import inspect
import json
from pathlib import Path
import re

import clang.cindex as ci
from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.cpp.model_mode.headers import MODEL_HEADERS_DIR
from colcon_rsia.frontend.cpp.model_mode.recovery import kinds
from colcon_rsia.frontend.cpp.model_mode.recovery import rules
from colcon_rsia.frontend.cpp.model_mode.recovery import store
from colcon_rsia.package import analysis
from colcon_rsia.package.coverage import workspace_report
from colcon_rsia.render.coverage import coverage_to_text
from conftest import analyze_source
import pytest

EXAMPLES = [(rule, example) for rule in rules.RULES
            for example in rule.examples]


def test_every_rule_has_a_worked_example():
    assert [r.id for r in rules.RULES if not r.examples] == []
    ids = [r.id for r in rules.RULES]
    assert len(ids) == len(set(ids))


@pytest.mark.parametrize(
    'rule, example', EXAMPLES,
    ids=[f'{rule.id}-{i}' for i, (rule, _) in enumerate(EXAMPLES)])
def test_a_rule_answers_its_example(rule, example):
    lines = [example.code]

    def read_line(file, line):
        return lines[line - 1] if 0 < line <= len(lines) else ''
    found = rules.find_repairs(
        [(example.message, 'a.cpp', 1, example.column)], read_line,
        texts=[example.code])
    assert set(found) == set(example.expected), found
    # (a rule that reads notes makes nothing of an example without them)
    assert set(found.values()) == ({rule.id} if example.expected else set())
    # no rule before it in the table takes the example
    seen = rules.Seen(
        message=example.message, file='a.cpp', line=1,
        column=example.column, text=example.code,
        subject=None, after='', read_line=read_line, texts=(example.code,),
        stand_in=None)
    earlier = rules.RULES[:rules.RULES.index(rule)]
    assert not [r.id for r in earlier
                if r.id != 'reserved-attribute' and r.applies(seen)]


# namespaces, prefixes and names of libraries that a rule must not spell:
# what a name becomes follows from C++ and how the code uses it
LIBRARIES = (
    'cv', 'opencv', 'eigen', 'pcl', 'qt', 'qobject', 'qstring', 'boost',
    'lanelet', 'autoware', 'rviz', 'ogre', 'ceres', 'cuda', 'nvinfer',
    'pybind', 'fmt', 'gazebo', 'moveit', 'tf2', 'rclcpp', 'ros', 'grid_map',
    'nav2', 'yaml', 'thrust', 'tensorrt', 'glog', 'gflags', 'absl')


def _code_words(function):
    """The identifiers and string contents of a function, comments aside.

    (A lambda's source is the line it is on, which may not tokenize alone:
    its comments and docstrings are cut by pattern.)
    """
    source = inspect.getsource(function)
    source = re.sub(r'"{3}[\s\S]*?"{3}', ' ', source)
    source = re.sub(r'#[^\n]*', ' ', source)
    return [w.lower() for w in re.findall(r'[A-Za-z_]\w*', source)]


def test_no_rule_names_a_library():
    named = []
    for rule in rules.RULES:
        words = _code_words(rule.applies) + _code_words(rule.decide) + \
            re.findall(r'[a-z_]\w*', (rule.id + ' ' + rule.answers).lower())
        for example in rule.examples:
            words += re.findall(r'[A-Za-z_]\w*', example.code.lower())
        named += [(rule.id, w) for w in words if w in LIBRARIES]
    # the patterns of clang's messages the rules match
    for name, value in vars(rules).items():
        if isinstance(value, re.Pattern):
            named += [(name, w) for w in re.findall(
                r'[a-z_]\w+', value.pattern.lower()) if w in LIBRARIES]
    assert named == []


def test_the_rule_table_is_what_the_rules_are_made_of():
    # every kind a rule produces is a kind the header renders
    produced = {k for rule in rules.RULES for k in rule.produces}
    assert produced <= set(kinds.PRIORITY) | {
        kinds.MEMBER, kinds.MEMBER_TYPE, kinds.MEMBER_TEMPLATE,
        kinds.MEMBER_SCOPE, kinds.TEMPLATE_USE, kinds.STD_HEADER,
        kinds.NO_OVERRIDE, kinds.LITERAL, kinds.NO_HASH, kinds.MODEL_MEMBER}


def test_a_header_of_every_kind_of_repair_compiles(tmp_path):
    # one repair of each declaring kind, as the rules' examples make them,
    # rendered together and compiled alone
    repairs = {repair for _, example in EXAMPLES
               for repair in example.expected} | {
        (kinds.TYPE, 'lib::Widget'), (kinds.TYPE, 'lib::Grid'),
        (kinds.NAMESPACE, 'lib::inner'), (kinds.OBJECT, 'lib::handle'),
        (kinds.FUNCTION, 'compute'), (kinds.VALUE, 'lib::Mode'),
        (kinds.MEMBER_TEMPLATE, 'lib::Grid::at'),
        (kinds.MEMBER_SCOPE, 'lib::Grid::Base'),
        (kinds.HEADER, 'rsia_model/message.h')}
    header = tmp_path / 'repairs.h'
    store.add_repairs(str(header), 'a.cpp', repairs, 'test')
    # and its uses: each name usable as what it was declared as
    source = tmp_path / 'a.cpp'
    source.write_text(
        '#include "repairs.h"\n'
        'void use() {\n'
        '  lib::Widget w; lib::Widget * p = nullptr; (void)p; (void)w;\n'
        '  int n = lib::Grid::size(); (void)n;\n'
        '  lib::Grid::Ptr grid; (void)grid;\n'
        '  lib::draw(1, 2); compute(3);\n'
        '  auto h = lib::handle; (void)h;\n'
        '}\n')
    resource = sorted(glob.glob('/usr/lib/llvm-*/lib/clang/*'))[-1]
    tu = cpp.parse(ci.Index.create(), file=str(source),
                   arguments=['-x', 'c++', '-std=c++17',
                              '-I', MODEL_HEADERS_DIR, '-I', str(tmp_path)],
                   resource_dir=resource, working_directory=str(tmp_path))
    errors = [f'{d.location.line}: {d.spelling}' for d in tu.diagnostics
              if d.severity >= ci.Diagnostic.Error]
    assert errors == []
    # the records say which rule made each
    assert set(store.read_records(str(header)).values()) == {'test'}


NEWER_LIBRARY = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <tf2_ros/buffer.h>
class Node : public rclcpp::Node
{
public:
  Node() : rclcpp::Node("newer")
  {
    std::filesystem::path path("/tmp");
    auto qos = rclcpp::QoS(10);
    auto policy = qos.reliability();
    tf2_ros::Buffer::SharedPtr buffer;
    int flags = tf2_ros::Buffer::kDefaultFlags;
    pub_ = create_publisher<std_msgs::msg::String>("out", qos);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Node>());
}
"""


def test_a_model_class_answers_what_the_users_version_has(tmp_path):
    # a getter overload, a nested pointer type and a constant the model
    # lacks, and a standard namespace's type reached through another
    # header: each is repaired by a rule that names no library
    summary = analyze_source(tmp_path, 'newer', NEWER_LIBRARY)
    [unit] = summary.coverage.units
    assert unit.package_errors == 0, summary.diagnostics
    assert sorted((rule, kind, name) for rule, kind, name in unit.repairs
                  if rule != 'seeded') == [
        ('member-of-class', 'model-member:value',
         'tf2_ros::Buffer::kDefaultFlags'),
        ('model-overload', 'model-member:function',
         'rclcpp::QoS::reliability'),
        ('standard-header', 'std-header', 'filesystem'),
        ('type-in-class', 'model-member:type', 'tf2_ros::Buffer::SharedPtr'),
    ]
    [node] = summary.nodes
    [publisher] = node.publishers
    assert (publisher.topic, publisher.origin) == ('out', 'ast')
    # the model header on disk is as it was
    assert 'kDefaultFlags' not in (
        Path(MODEL_HEADERS_DIR) / 'tf2_ros' / 'buffer.h').read_text()
    # `colcon rsia coverage --repairs` says which rule repaired what, where
    text = coverage_to_text(workspace_report([summary]), repairs=True)
    assert '  repair model-overload: model-member:function ' \
        'rclcpp::QoS::reliability (src/newer.cpp)' in text.splitlines()
    assert 'repairs by rule: member-of-class 1, model-overload 1, ' \
        'standard-header 1, type-in-class 1' in text


def test_the_developer_docs_list_every_rule():
    text = (Path(__file__).resolve().parents[2] / 'docs' / 'developer' /
            'model-mode.md').read_text()
    table = text.split('<!-- rule-table -->')[1].split(
        '<!-- /rule-table -->')[0]
    documented = re.findall(r'^\| `([\w-]+)` \|', table, re.MULTILINE)
    assert documented == [rule.id for rule in rules.RULES]


# a member the model's boost::shared_ptr lacks: the model header that
# rsia_model/message.h includes itself is given the member
OWNER_BEFORE = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <boost/shared_ptr.hpp>

boost::shared_ptr<int> first, second;
ros::Publisher pub;

void tick(const ros::TimerEvent &)
{
  if (first.owner_before(second)) {
    pub.publish(std_msgs::String());
  }
}

int main(int argc, char ** argv)
{
  ros::init(argc, argv, "owner");
  ros::NodeHandle nh;
  pub = nh.advertise<std_msgs::String>("out", 1);
  ros::Timer timer = nh.createTimer(ros::Duration(0.1), tick);
  ros::spin();
}
"""


def test_a_member_added_to_a_header_the_catch_alls_include(tmp_path):
    summary = analyze_source(tmp_path, 'owner', OWNER_BEFORE)
    [unit] = summary.coverage.units
    assert [kind for _, kind, _ in unit.repairs] == ['model-member:function']
    # before: "no member named 'rsia_model' in the global namespace" in
    # boost/shared_ptr.hpp, where the added member names rsia_model::Any
    assert unit.errors == 0, summary.diagnostics


def test_every_model_header_begins_with_a_comment_line():
    # the members' catch-alls are declared ahead on that line (overlay)
    for path in Path(MODEL_HEADERS_DIR).rglob('*'):
        if path.is_file() and path.suffix != '.md':
            assert path.read_text().startswith('//'), path


# calls of a model class method, in a unit that starts with a catch-all
# member of that name: another unit's repair, shared with its package (in
# that unit a call matched no overload the model declares)
SEEDED_MODEL_MEMBER = r"""
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Relay : public rclcpp::Node
{
public:
  Relay() : Node("relay")
  {
    pub_ = create_publisher<std_msgs::msg::String>("out", 10);
    std::string name = "echo";
    echo_ = this->create_publisher<std_msgs::msg::String>(
      name, rclcpp::QoS(1));
    // the user's version has more parameters than the model's
    extra_ = create_publisher<std_msgs::msg::String>("extra", 1, 2, 3);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, echo_, extra_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Relay>());
}
"""


def test_a_member_added_to_a_model_class_is_its_last_choice(tmp_path):
    shared = tmp_path / 'b' / 'rsia' / 'stubs' / 'rsia_model' / 'repair' / \
        store.SHARED_REPAIRS
    shared.parent.mkdir(parents=True)
    shared.write_text(json.dumps(
        [['model-member:function', 'rclcpp::Node::create_publisher']]))
    summary = analyze_source(tmp_path, 'relay', SEEDED_MODEL_MEMBER,
                             repair=analysis.REPAIR_WHEN_IT_PAYS)
    [unit] = summary.coverage.units
    assert [(rule, kind) for rule, kind, _ in unit.repairs] == [
        (store.SEEDED, 'model-member:function')]
    # the calls the model's overload matches resolve there, not ambiguous
    # between it and the added member; the call it does not match, to
    # the added member
    assert unit.errors == 0, summary.diagnostics
    [node] = summary.nodes
    assert sorted((p.topic, p.origin) for p in node.publishers) == [
        ('echo', 'ast'), ('extra', 'ast'), ('out', 'ast')]
