# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""A hostile contributor's files and a careless user's input (issue 16).

Special files, huge files, crafted names and summaries, injected Markdown:
each case gets one clear message, no traceback, no hang, and the other
packages' results.
"""

import json
import os
from pathlib import Path
import resource
import signal
import subprocess
import time

from conftest import colcon_executable
from helpers import catkin_package
from helpers import GOOD_NODE
from helpers import read_summary
import pytest

# a hang is what the special files caused: anything near this is one
HANG_TIMEOUT_S = 300
# /dev/zero read whole grew colcon to 24 GB; an analysis stays far below
MEMORY_LIMIT_BYTES = 4 * 1024 ** 3

PYTHON_PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>{name}</name><version>0.0.1</version><description>d</description>
  <maintainer email="dev@example.com">m</maintainer><license>MIT</license>
  <export><build_type>ament_python</build_type></export>
</package>
"""
PYTHON_NODE = """import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__('talker')
        self.pub = self.create_publisher(String, 'chatter', 10)
        self.create_timer(0.5, self.tick)

    def tick(self):
        self.pub.publish(String())


def main():
    rclpy.init()
    rclpy.spin(Talker())
"""


def _limit_memory():
    resource.setrlimit(resource.RLIMIT_AS,
                       (MEMORY_LIMIT_BYTES, MEMORY_LIMIT_BYTES))


def _colcon(args, *, cwd, env=None):
    """colcon with a memory limit and a timeout (hangs fail, not block)."""
    environment = dict(os.environ)
    environment['COLCON_HOME'] = str(Path(cwd) / '.colcon_home')
    environment.update(env or {})
    return subprocess.run(
        [colcon_executable()] + args, cwd=str(cwd), env=environment,
        capture_output=True, text=True, timeout=HANG_TIMEOUT_S,
        preexec_fn=_limit_memory)


def _analyze(root, *, env=None):
    return _colcon(['rsia', 'analyze', '--base-paths', str(root / 'src'),
                    '--build-base', str(root / 'build')], cwd=root, env=env)


def _python_package(root, name, modules, *, setup=None):
    package = root / 'src' / name
    (package / name).mkdir(parents=True)
    (package / 'package.xml').write_text(PYTHON_PACKAGE_XML.format(name=name))
    (package / name / '__init__.py').write_text('')
    scripts = [f"'{m} = {name}.{m}:main'" for m in modules]
    (package / 'setup.py').write_text(
        'from setuptools import setup\n'
        f"setup(name='{name}', entry_points={{'console_scripts': "
        f"[{', '.join(scripts)}]}})\n" if setup is None else setup)
    for module, content in modules.items():
        path = package / name / f'{module}.py'
        if content is not None:
            path.write_text(content)
    return package


def _lines(result, package):
    return [line for line in result.stdout.splitlines()
            if line.startswith(f'rsia: {package}: ')]


def _no_traceback(result):
    assert 'Traceback' not in result.stdout + result.stderr
    assert 'internal error' not in result.stdout + result.stderr


# --- 1, 12: special and huge files -------------------------------------------

@pytest.fixture(scope='module')
def special_files(tmp_path_factory):
    root = tmp_path_factory.mktemp('special')
    # a source, a header, an absolute include, CMakeLists.txt, FIFOs
    package = catkin_package(root, 'zero_source', {
        'good.cpp': GOOD_NODE, 'zero.cpp': None})
    os.symlink('/dev/zero', package / 'src' / 'zero.cpp')
    package = catkin_package(root, 'zero_header', {
        'good.cpp': '#include "zero.h"\n' + GOOD_NODE})
    os.symlink('/dev/zero', package / 'src' / 'zero.h')
    catkin_package(root, 'zero_absolute', {
        'good.cpp': '#include "/dev/zero"\n' + GOOD_NODE})
    package = catkin_package(root, 'zero_cmake', {'good.cpp': GOOD_NODE})
    (package / 'CMakeLists.txt').unlink()
    os.symlink('/dev/zero', package / 'CMakeLists.txt')
    package = catkin_package(root, 'fifo_source', {
        'good.cpp': GOOD_NODE, 'fifo.cpp': None})
    os.mkfifo(package / 'src' / 'fifo.cpp')
    package = catkin_package(root, 'fifo_header', {
        'good.cpp': '#include "fifo.h"\n' + GOOD_NODE})
    os.mkfifo(package / 'src' / 'fifo.h')
    # Python: an entry module, setup.py, a secret outside the package
    package = _python_package(root, 'py_zero', {
        'talker': PYTHON_NODE, 'zero': None})
    os.symlink('/dev/zero', package / 'py_zero' / 'zero.py')
    package = _python_package(root, 'py_fifo', {
        'talker': PYTHON_NODE, 'fifo': None})
    os.mkfifo(package / 'py_fifo' / 'fifo.py')
    package = _python_package(root, 'py_setup', {'talker': PYTHON_NODE})
    (package / 'setup.py').unlink()
    os.symlink('/dev/zero', package / 'setup.py')
    package = _python_package(root, 'py_secret', {
        'talker': PYTHON_NODE, 'environ': None})
    os.symlink('/proc/self/environ', package / 'py_secret' / 'environ.py')
    _python_package(root, 'py_good', {'talker': PYTHON_NODE})
    return root, _analyze(root)


def test_special_files_end_in_one_line_per_package(special_files):
    root, result = special_files
    assert result.returncode == 0, result.stderr
    _no_traceback(result)
    for name in ('zero_source', 'zero_header', 'zero_absolute', 'zero_cmake',
                 'fifo_source', 'fifo_header', 'py_zero', 'py_fifo',
                 'py_setup', 'py_secret', 'py_good'):
        assert len(_lines(result, name)) == 1, name


@pytest.mark.parametrize('package, file, reason', [
    ('zero_source', 'src/zero.cpp', "is a link to '/dev/zero'"),
    ('fifo_source', 'src/fifo.cpp', 'is not a regular file (a FIFO)'),
    ('zero_header', "src/good.cpp: includes 'src/zero.h'",
     "is a link to '/dev/zero'"),
    ('fifo_header', "src/good.cpp: includes 'src/fifo.h'",
     'is not a regular file (a FIFO)'),
    ('zero_absolute', "src/good.cpp: includes '/dev/zero'",
     'is not a regular file (a character device)'),
])
def test_special_cpp_file_is_named_and_the_node_analyzed(
        special_files, package, file, reason):
    root, _ = special_files
    summary = read_summary(root, package)
    assert any(d.startswith(file) and reason in d
               for d in summary['diagnostics']), summary['diagnostics']
    node = next(n for n in summary['nodes'] if n['executable'] == 'good')
    assert [(p['topic'], p['label']) for p in node['publishers']] == \
        [('out', 'independent')]


def test_cmakelists_linked_to_dev_zero_is_named(special_files):
    root, _ = special_files
    summary = read_summary(root, 'zero_cmake')
    assert any(d.startswith('CMakeLists.txt: ') and '/dev/zero' in d
               for d in summary['diagnostics']), summary['diagnostics']
    # a source with main() is still a node, named after its file
    assert [n['id'] for n in summary['nodes']] == ['zero_cmake/good']


@pytest.mark.parametrize('package, file, reason', [
    ('py_zero', 'py_zero/zero.py', "is a link to '/dev/zero'"),
    ('py_fifo', 'py_fifo/fifo.py', 'is not a regular file (a FIFO)'),
    ('py_secret', 'py_secret/environ.py', "is a link to '/proc/"),
])
def test_special_python_module_is_named_and_the_node_analyzed(
        special_files, package, file, reason):
    root, _ = special_files
    summary = read_summary(root, package)
    assert any(file in d and reason in d for d in summary['diagnostics']), \
        summary['diagnostics']
    assert [n['id'] for n in summary['nodes']] == [f'{package}/talker']


def test_setup_py_linked_to_dev_zero_is_named(special_files):
    root, _ = special_files
    summary = read_summary(root, 'py_setup')
    assert any(d.startswith('setup.py: ') and '/dev/zero' in d
               for d in summary['diagnostics']), summary['diagnostics']


def test_secret_outside_the_package_is_never_read(special_files):
    root, _ = special_files
    text = (root / 'build' / 'py_secret' / 'rsia' / 'summary.json').read_text()
    assert 'COLCON_HOME' not in text


def test_other_packages_are_intact(special_files):
    root, _ = special_files
    [node] = read_summary(root, 'py_good')['nodes']
    assert [(p['topic'], p['label'], p['pattern'])
            for p in node['publishers']] == \
        [('chatter', 'independent', 'no_subscribers')]


def test_files_above_the_size_limit_are_named_with_the_limit(tmp_path):
    # the limit is configurable: 1 MB here, so that the files stay small
    filler = '# filler\n' * 150_000   # 1.35 MB
    _python_package(tmp_path, 'py_huge', {
        'talker': PYTHON_NODE, 'big': filler})
    catkin_package(tmp_path, 'cpp_huge', {
        'good.cpp': GOOD_NODE, 'big.cpp': GOOD_NODE + '//' + filler})
    result = _analyze(tmp_path, env={'COLCON_RSIA_MAX_FILE_MB': '1'})
    assert result.returncode == 0, result.stderr
    _no_traceback(result)
    message = 'is larger than the size limit (1.3 MB > 1 MB)'
    hint = 'COLCON_RSIA_MAX_FILE_MB'
    diagnostics = read_summary(tmp_path, 'py_huge')['diagnostics']
    assert any('py_huge/big.py' in d and message in d and hint in d
               for d in diagnostics), diagnostics
    diagnostics = read_summary(tmp_path, 'cpp_huge')['diagnostics']
    assert any(d.startswith('src/big.cpp: ') and message in d and hint in d
               for d in diagnostics), diagnostics
    assert [n['id'] for n in read_summary(tmp_path, 'cpp_huge')['nodes']] == \
        ['cpp_huge/good']


# --- 2: Markdown injection in summary.md -------------------------------------

INJECTED = [
    '![pwned](https://evil.example/i.png)',
    '[click](https://evil.example)',
    '<img src=x onerror=alert(1)>',
    'https://evil.example/x',
    'www.evil.example',
    '**bold**',
    '_emphasis_',
    '\n### All clear: no rate impact\n',
    '`` ` ``',
    'a|b\r\n| --- |',
    '@everyone',
    '&lt;b&gt;',
]
# the markup summary.md itself makes
OWN_STRONG = ('Changed', 'Rate-aware impact', 'Stopped at independent edges')


def _injected_system():
    from colcon_rsia.summary.kinds import DEPENDENT
    from colcon_rsia.summary.kinds import INDEPENDENT
    from colcon_rsia.summary.kinds import PATTERN_NONE
    from colcon_rsia.summary.nodes import LabelledPublisher
    from colcon_rsia.summary.nodes import Node
    from colcon_rsia.summary.nodes import NodeSubscriber
    from colcon_rsia.summary.package_summary import PackageSummary
    from colcon_rsia.system.load import load_system
    nodes = []
    for number, evil in enumerate(INJECTED):
        timer = number % 2 == 0
        nodes.append(Node(
            id=f'evil/n{number}{evil}', package='evil',
            executable=f'n{number}{evil}', kind='executable',
            publishers=[LabelledPublisher(
                topic=f'/t{number + 1}{evil}', topic_is_literal=True,
                msg_type='x', api='a', handle=None, namespace='',
                location='f.cpp:1',
                label=INDEPENDENT if timer else DEPENDENT,
                pattern=f'timer{evil}' if timer else PATTERN_NONE,
                rate_hz=None)],
            subscribers=[NodeSubscriber(
                topic=f'/t{number}{INJECTED[number - 1]}',
                topic_is_literal=True, msg_type='x', api='a',
                callback=None, namespace='', location='f.cpp:2')]))
    return load_system([PackageSummary(
        package='evil', path='/nowhere', tool_version='0', nodes=nodes)])


def _markup_from(markdown_text):
    """(kind, text) of every piece of markup a GFM renderer makes."""
    from markdown_it import MarkdownIt
    renderer = MarkdownIt('gfm-like')  # CommonMark, tables, linkify
    tokens = renderer.parse(markdown_text)
    found = []

    def walk(tokens):
        for i, token in enumerate(tokens):
            if token.type in ('link_open', 'image', 'html_inline',
                              'html_block', 'em_open', 's_open'):
                found.append((token.type, token.content))
            if token.type == 'heading_open':
                found.append(('heading', tokens[i + 1].content))
            if token.type == 'strong_open':
                found.append(('strong', tokens[i + 1].content))
            walk(token.children or [])
    walk(tokens)
    return found


def test_summary_md_shows_data_and_never_markup_from_it():
    from colcon_rsia.report import build_report
    from colcon_rsia.report.markdown import render_summary
    system = _injected_system()
    changed = sorted(system.instances)[:1]
    summary = render_summary(build_report(
        system, changed=changed, since=INJECTED[0],
        reasons={changed[0]: [f'src/{e}.cpp changed' for e in INJECTED]}))
    markup = _markup_from(summary)
    assert [m for m in markup if m[0] not in ('heading', 'strong', 'em_open')
            ] == []
    assert [m for m in markup if m[0] == 'heading'] == \
        [('heading', 'colcon-rsia: rate impact')]
    for kind, content in markup:
        if kind == 'strong':
            assert content.startswith(OWN_STRONG), content
    # one em: the footer
    assert [m for m in markup if m[0] == 'em_open'] == [('em_open', '')]
    # every line is ours: a bullet, a table row, a heading, text we wrote
    for line in summary.splitlines():
        assert line == '' or line.startswith(('- ', '| ', '### ', '**', '_',
                                              'No ', '… ')), line


def test_code_spans_hold_any_value():
    from colcon_rsia.report.markdown import code
    from markdown_it import MarkdownIt
    for value in ['a`b', '``x', 'x``', '`', 'a ``` b', 'caf\udce9']:
        [paragraph] = [t for t in MarkdownIt('commonmark').parse(code(value))
                       if t.type == 'inline']
        [span] = paragraph.children
        assert span.type == 'code_inline'
        expected = value if value != 'caf\udce9' else 'caf\\xe9'
        assert span.content == expected


# --- 3: package names that leave the build base -------------------------------

@pytest.mark.parametrize('name', [
    '../../../escaped_pkg', 'a/b', '..', '/abs/pkg'])
def test_package_name_leaving_the_build_base_is_skipped(tmp_path, name):
    from colcon_rsia.package import runner
    package = _python_package(tmp_path, 'talker_pkg', {'talker': PYTHON_NODE})
    build_base = tmp_path / 'ws' / 'build'
    outcome = runner.analyze(
        name=name, package_type='ros.ament_python', path=str(package),
        build_base=os.path.join(build_base, name))
    assert outcome.summary is None
    assert 'is not a plain directory name' in outcome.line()
    assert 'skipped' in outcome.line()
    written = [p for p in tmp_path.rglob('summary.json')]
    assert written == []


# --- 4: file names that are not UTF-8 ----------------------------------------

LATIN1_NAME = os.fsdecode(b'caf\xe9_node')


def test_non_utf8_file_names_are_analyzed_and_shown_escaped(tmp_path):
    package = catkin_package(tmp_path, 'latin1_names', {'good.cpp': GOOD_NODE})
    source = package / 'src' / f'{LATIN1_NAME}.cpp'
    (package / 'src' / 'good.cpp').rename(source)
    raw_source = os.fsencode(source)
    (package / 'CMakeLists.txt').write_bytes(
        b'project(latin1_names)\nadd_executable(latin_node src/' +
        os.path.basename(raw_source) + b')\n')
    database = tmp_path / 'build' / 'latin1_names' / 'compile_commands.json'
    database.write_bytes(
        b'[{"directory": "' + os.fsencode(database.parent) + b'", "file": "' +
        raw_source + b'", "command": "c++ -std=c++17 -c ' + raw_source +
        b'"}]')
    (package / 'scripts').mkdir()
    script = package / 'scripts' / LATIN1_NAME
    script.write_text('#!/usr/bin/env python3\nimport rospy\n'
                      'from std_msgs.msg import String\n'
                      "rospy.init_node('n')\n"
                      "pub = rospy.Publisher('py_out', String)\n"
                      'rate = rospy.Rate(2)\n'
                      'while True:\n    pub.publish(String())\n'
                      '    rate.sleep()\n')
    script.chmod(0o755)
    result = _analyze(tmp_path)
    assert result.returncode == 0, result.stderr
    _no_traceback(result)
    summary = read_summary(tmp_path, 'latin1_names')
    # CMake garbles such names in its codemodel: not asked
    assert summary['diagnostics'] == [
        'CMakeLists.txt is not UTF-8, which CMake cannot report file names '
        'of; CMakeLists.txt read by the fallback reader']
    nodes = {n['id']: n for n in summary['nodes']}
    escaped = 'caf\\xe9_node'
    assert sorted(nodes) == [
        f'latin1_names/{escaped}', 'latin1_names/latin_node']
    assert nodes['latin1_names/latin_node']['sources'] == [
        f'src/{escaped}.cpp']
    assert nodes[f'latin1_names/{escaped}']['sources'] == [
        f'scripts/{escaped}']
    for node in nodes.values():
        assert [p['label'] for p in node['publishers']] == ['independent']
        assert node['publishers'][0]['location'].startswith(
            node['sources'][0] + ':')

    report = tmp_path / 'report'
    result = _colcon(['rsia', 'report', '--build-base',
                      str(tmp_path / 'build'), '--base-paths',
                      str(tmp_path / 'src'), '--output', str(report),
                      '--changed', f'latin1_names/{escaped}'], cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    _no_traceback(result)
    page = (report / 'index.html').read_text(encoding='utf-8')
    assert escaped in page
    assert escaped in (report / 'summary.md').read_text(encoding='utf-8')


def test_report_is_written_whole_or_not_at_all(tmp_path, monkeypatch):
    from colcon_rsia.report import writer
    system = _injected_system()
    writer.write_report(system, str(tmp_path), dot_executable='/nonexistent')
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert before['index.html']
    # a report of other changes: each of its files would differ
    changed = sorted(system.instances)[:1]

    def broken(data):
        raise UnicodeEncodeError('utf-8', 'x', 0, 1, 'surrogates not allowed')
    monkeypatch.setattr(writer, 'render_summary', broken)
    with pytest.raises(UnicodeEncodeError):
        writer.write_report(system, str(tmp_path), changed=changed,
                            dot_executable='/nonexistent')
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before


# --- 5: --since '' --------------------------------------------------------------

@pytest.mark.parametrize('subverb', ['impact', 'report'])
def test_empty_since_is_one_clear_error(system_workspace, tmp_path, subverb):
    args = ['rsia', subverb, '--base-paths', str(system_workspace.src),
            '--since', '']
    if subverb == 'report':
        args += ['--output', str(tmp_path / 'report')]
    result = system_workspace.colcon(*args)
    assert result.returncode == 1
    _no_traceback(result)
    assert '--since needs a git revision, got an empty string' in \
        result.stderr
    assert not (tmp_path / 'report').exists()


# --- 8: option values -----------------------------------------------------------

@pytest.mark.parametrize('jobs', ['-3', '0', 'many'])
def test_bad_jobs_is_a_usage_error(tmp_path, jobs):
    catkin_package(tmp_path, 'good', {'good.cpp': GOOD_NODE})
    result = _colcon(['rsia', 'analyze', '--base-paths', str(tmp_path / 'src'),
                      '--jobs', jobs], cwd=tmp_path)
    # a usage error, which exits 1 like every error (2 is --fail-on's)
    assert result.returncode == 1
    _no_traceback(result)
    assert f"argument --jobs: '{jobs}' is not a whole number of 1 or more" \
        in result.stderr
    assert 'please report it' not in result.stdout


# --- 10: file modes -------------------------------------------------------------

def test_summaries_and_caches_follow_the_umask(tmp_path):
    catkin_package(tmp_path, 'good', {'good.cpp': GOOD_NODE})
    old = os.umask(0o027)
    try:
        result = _analyze(tmp_path)  # the child inherits the umask
    finally:
        os.umask(old)
    assert result.returncode == 0, result.stderr
    rsia = tmp_path / 'build' / 'good' / 'rsia'
    files = [rsia / 'summary.json'] + list((rsia / 'cache').iterdir())
    assert len(files) == 2
    for file in files:
        assert oct(file.stat().st_mode & 0o777) == oct(0o640), file


# --- 6: crafted or damaged summaries ------------------------------------------

def _crafted(summary, change):
    data = json.loads(json.dumps(summary))
    change(data)
    return data


def _set_node(key, value):
    def change(data):
        data['nodes'][0][key] = value
    return change


def _set_publisher(key, value):
    def change(data):
        data['nodes'][0]['publishers'][0][key] = value
    return change


def _duplicate_node(data):
    data['nodes'].append(dict(data['nodes'][0]))


CRAFTED = {
    'id int': (_set_node('id', 7), 'summary.nodes[0].id is not a str: 7'),
    'id null': (_set_node('id', None), 'summary.nodes[0].id is not a str'),
    'id list': (_set_node('id', ['a']), 'summary.nodes[0].id is not a str'),
    'namespace int': (_set_node('namespace', 3),
                      'summary.nodes[0].namespace is not a str: 3'),
    'topic int': (_set_publisher('topic', 5),
                  'summary.nodes[0].publishers[0].topic is not a str: 5'),
    'rate string': (_set_publisher('rate_hz', 'fast'),
                    'rate_hz is not a finite number'),
    'rate NaN': (_set_publisher('rate_hz', float('nan')),
                 'rate_hz is not a finite number: nan'),
    'rate infinite': (_set_publisher('rate_hz', float('inf')),
                      'rate_hz is not a finite number: inf'),
    'duplicate id': (_duplicate_node,
                     "node id 'sysbot_drivers/base_driver' appears more "
                     'than once'),
}


@pytest.mark.parametrize('case', sorted(CRAFTED) + ['deep nesting'])
def test_crafted_summary_is_one_warning_and_hides_nothing(
        system_workspace, tmp_path, case):
    build = tmp_path / 'build'
    for package in ('sysbot_drivers', 'sysbot_navigation',
                    'sysbot_perception'):
        target = build / package / 'rsia'
        target.mkdir(parents=True)
        (target / 'summary.json').write_text(json.dumps(
            system_workspace.summary(package)))
    crafted = build / 'sysbot_drivers' / 'rsia' / 'summary.json'
    if case == 'deep nesting':
        crafted.write_text('{"nodes": ' + '[' * 100_000 + ']' * 100_000 + '}')
        message = 'nested too deeply'
    else:
        change, message = CRAFTED[case]
        crafted.write_text(json.dumps(_crafted(
            system_workspace.summary('sysbot_drivers'), change)))
    for subverb in (['graph', '--format', 'json'],
                    ['impact', '--all', '--format', 'json'],
                    ['report', '--output', str(tmp_path / 'report')]):
        result = _colcon(
            ['rsia', *subverb, '--base-paths', str(system_workspace.src),
             '--build-base', str(build)], cwd=tmp_path)
        assert result.returncode == 0, (subverb, result.stderr)
        _no_traceback(result)
        [warning] = [line for line in result.stderr.splitlines()
                     if 'summary' in line]
        assert str(crafted) in warning and message in warning, warning
        if subverb[0] == 'graph':
            ids = {n['id'] for n in json.loads(result.stdout)['nodes']}
            assert 'sysbot_navigation/planner' in ids
            assert not any(i.startswith('sysbot_drivers/') for i in ids)
        if subverb[0] == 'impact':
            # strict JSON: no NaN or Infinity
            json.loads(result.stdout, parse_constant=pytest.fail)


# --- 9: messages that say what is wrong -----------------------------------------

@pytest.mark.parametrize('words, message', [
    (['/nonexistent.launch'], '--launch /nonexistent.launch: file not found'),
    (['/tmp'], '--launch /tmp: not a regular file'),
    (['{launch}', 'extra'], 'a launch file takes only name:=value '
     "arguments, got 'extra'"),
])
def test_launch_argument_messages(system_workspace, tmp_path, words, message):
    launch = tmp_path / 'empty.launch'
    launch.write_text('<launch/>')
    words = [w.format(launch=launch) for w in words]
    message = message.format(launch=launch)
    result = system_workspace.colcon(
        'rsia', 'impact', '--base-paths', str(system_workspace.src),
        '--launch', *words, '--all')
    assert result.returncode == 1
    _no_traceback(result)
    assert message in result.stderr
    assert 'unknown package' not in result.stderr


# Ctrl-C during `colcon build --event-handlers rsia+`: one package whose
# analysis takes many parses (units only the compile database names: the
# build compiles none of them) and one whose build waits long
MANY_UNITS = 60
HEAVY_UNIT = """#include <iostream>
#include <map>
#include <regex>
#include <string>
int unit_{n}() {{ std::map<std::string, std::regex> m; return m.size(); }}
"""


def _interrupt_workspace(root):
    parses = root / 'src' / 'many_parses'
    (parses / 'src').mkdir(parents=True)
    (parses / 'src' / 'main.cpp').write_text('int main() { return 0; }\n')
    for n in range(MANY_UNITS):
        (parses / 'src' / f'unit_{n}.cpp').write_text(HEAVY_UNIT.format(n=n))
    (parses / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.10)\nproject(many_parses CXX)\n'
        'add_executable(many_parses_node src/main.cpp)\n'
        'file(GLOB units src/unit_*.cpp)\n'
        'add_library(units EXCLUDE_FROM_ALL ${units})\n')
    waiting = root / 'src' / 'long_build'
    waiting.mkdir(parents=True)
    (waiting / 'CMakeLists.txt').write_text(
        'cmake_minimum_required(VERSION 3.10)\nproject(long_build NONE)\n'
        'add_custom_target(wait ALL COMMAND sleep 120)\n')


def test_a_job_killed_by_ctrl_c_is_an_interrupt_and_a_failed_make_is_not():
    # which of colcon and the job's process Ctrl-C reaches first varies:
    # colcon reports SIGINT_RESULT, or the job's own result, killed by
    # SIGINT (-2); make's 2 is a failed build
    from colcon_core.subprocess import SIGINT_RESULT
    from colcon_rsia.event_handler.rsia import _is_interrupt
    assert _is_interrupt(SIGINT_RESULT)
    assert _is_interrupt(-signal.SIGINT) and _is_interrupt('-2')
    assert not _is_interrupt(2) and not _is_interrupt(0)
    assert not _is_interrupt(-signal.SIGTERM)


# Ctrl-C while another package builds: colcon's executor stops its jobs
# and tells the event handlers. (After the last build job, while colcon
# waits for the analysis, the interrupt ends the analysis too, through the
# interpreter's exit, but when colcon's own code sees it varies: not tested.)
def test_ctrl_c_stops_the_build_and_the_analysis_promptly(tmp_path):
    _interrupt_workspace(tmp_path)
    environment = dict(os.environ)
    environment['COLCON_HOME'] = str(tmp_path / '.colcon_home')
    build = subprocess.Popen(
        [colcon_executable(), 'build', '--event-handlers', 'rsia+',
         'console_cohesion-', '--cmake-args',
         '-DCMAKE_EXPORT_COMPILE_COMMANDS=ON'],
        cwd=str(tmp_path), env=environment, stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT, text=True, start_new_session=True)
    lines = []
    try:
        for line in build.stdout:
            lines.append(line)
            if line.startswith('Finished <<< many_parses'):
                break
        # the analysis of many_parses has begun (60 parses, many seconds);
        # long_build is still building: Ctrl-C reaches the whole process
        # group, as from a terminal
        time.sleep(1.0)
        os.killpg(build.pid, signal.SIGINT)
        interrupted = time.monotonic()
        lines += build.stdout.readlines()
        build.wait(timeout=HANG_TIMEOUT_S)
        stopped_after = time.monotonic() - interrupted
    finally:
        if build.poll() is None:
            os.killpg(build.pid, signal.SIGKILL)
            build.wait()
    output = ''.join(lines)
    assert 'Finished <<< many_parses' in output, output
    assert 'rsia: interrupted' in output, output
    assert 'Traceback' not in output, output
    # colcon's own jobs stop within a second or two; the analysis adds at
    # most the parse under way (before: it went on through all 60 units)
    assert stopped_after < 8.0, (stopped_after, output)
    # nothing half written: the interrupted analysis wrote no summary, the
    # package whose build was interrupted was not analysed
    rsia = tmp_path / 'build' / 'many_parses' / 'rsia'
    assert not (rsia / 'summary.json').exists(), output
    assert not (tmp_path / 'build' / 'long_build' / 'rsia').exists()
