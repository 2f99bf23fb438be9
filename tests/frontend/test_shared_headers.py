# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Exact mode: the system headers a package's units share, precompiled once.

The units of test_workspaces/ros1 (compiled by the session fixture) are
parsed with and without the precompiled header their package shares: the
facts and the files read must be the same.
"""

import os
from types import SimpleNamespace

from colcon_rsia.frontend import cpp
from colcon_rsia.frontend.compile_db import find_resource_dir
from colcon_rsia.frontend.compile_db import load_compile_database
from colcon_rsia.frontend.cpp import shared_headers
from model_sources import parse_unit
import pytest


def test_leading_includes_are_the_block_a_source_begins_with():
    text = (
        '// Copyright\n'
        '/* a comment\n'
        '   #include <not/this.h> */\n'
        '#pragma once\n'
        '#include "own/header.h"\n'
        '#include <ros/ros.h>  // the API\n'
        '\n'
        '#  include <std_msgs/String.h>\n'
        '#define FAST 1\n'
        '#include <after/a/define.h>\n')
    assert shared_headers.leading_includes(text) == [
        'ros/ros.h', 'std_msgs/String.h']


def test_leading_includes_end_at_code_or_a_condition():
    assert shared_headers.leading_includes(
        '#include <a.h>\nint x;\n#include <b.h>\n') == ['a.h']
    assert shared_headers.leading_includes(
        '#ifdef X\n#include <a.h>\n#endif\n') == []


def _entry(path, arguments=('-std=c++17',), directory='/tmp'):
    return SimpleNamespace(file=str(path), arguments=list(arguments),
                           directory=directory)


def _plan(tmp_path, sources, arguments=None):
    entries = []
    for name, text in sources.items():
        path = tmp_path / name
        path.write_text(text)
        entries.append(_entry(path) if arguments is None
                       else _entry(path, arguments[name]))
    return {os.path.basename(f): text
            for f, text in shared_headers.plan(entries).items()}


def test_units_share_only_the_headers_every_one_of_them_includes(tmp_path):
    plans = _plan(tmp_path, {
        'a.cpp': '#include <vector>\n#include <map>\n#include <string>\n',
        'b.cpp': '#include <string>\n#include <vector>\nint b;\n',
    })
    # never a header a unit does not include (<map> could clash with b's
    # own names); in the order of the first unit
    assert plans == {'a.cpp': '#include <vector>\n#include <string>\n',
                     'b.cpp': '#include <vector>\n#include <string>\n'}


def test_a_unit_without_those_headers_does_not_stop_the_others(tmp_path):
    plans = _plan(tmp_path, {
        'a.cpp': '#include <vector>\n#include <map>\n',
        'b.cpp': '#include <vector>\n#include <map>\n',
        'c.cpp': '#include "own.h"\n',
        'd.cpp': '#include <string>\n#include <vector>\n',
        'e.cpp': '#include <string>\n',
    })
    # <vector> is the header most units include: a, b and d share it; e
    # alone is left with <string>, c with nothing
    assert plans == dict.fromkeys(('a.cpp', 'b.cpp', 'd.cpp'),
                                  '#include <vector>\n')


def test_a_unit_alone_or_with_other_flags_shares_nothing(tmp_path):
    assert _plan(tmp_path, {'a.cpp': '#include <vector>\n'}) == {}
    assert _plan(tmp_path, {
        'a.cpp': '#include <vector>\n', 'b.cpp': '#include <vector>\n',
    }, arguments={'a.cpp': ['-std=c++17', '-DFAST'],
                  'b.cpp': ['-std=c++17']}) == {}


def test_a_workspace_header_is_never_shared(tmp_path):
    include = tmp_path / 'include' / 'mine'
    include.mkdir(parents=True)
    (include / 'node.h').write_text('int mine();\n')
    arguments = ['-std=c++17', '-I', str(tmp_path / 'include')]
    sources = {'a.cpp': '#include <mine/node.h>\n#include <vector>\n',
               'b.cpp': '#include <mine/node.h>\n#include <vector>\n'}
    plans = _plan(tmp_path, sources, arguments=dict.fromkeys(
        sources, arguments))
    assert plans == dict.fromkeys(sources, '#include <vector>\n')


def test_a_precompiled_header_that_reaches_the_workspace_is_not_used(
        tmp_path):
    include = tmp_path / 'include'
    include.mkdir()
    (include / 'system_looking.h').write_text('#include "mine.h"\n')
    (include / 'mine.h').write_text('int mine();\n')
    assert shared_headers.precompiled(
        str(tmp_path / 'pch'), '#include <system_looking.h>\n',
        ['-std=c++17', '-I', str(include)], str(tmp_path),
        find_resource_dir()) is None


def _units(workspace, package):
    path = workspace.build_base / package / 'compile_commands.json'
    src = str(workspace.src / package) + '/'
    return [e for e in load_compile_database(str(path))
            if e.file.startswith(src)] if path.is_file() else []


# the packages with two units or more of one target that begin with
# system headers (rsia_clocks builds each unit with its own flags)
ROS1_PACKAGES_WITH_UNITS_TO_SHARE = (
    'rsia_control', 'rsia_drivers', 'rsia_localization', 'rsia_perception')


@pytest.mark.parametrize('package', ROS1_PACKAGES_WITH_UNITS_TO_SHARE)
def test_shared_headers_give_the_same_facts_and_inputs(
        ros1_workspace, package, tmp_path):
    entries = _units(ros1_workspace, package)
    plans = shared_headers.plan(entries)
    assert len(plans) >= 2, f'{package}: no header shared'
    package_path = str(ros1_workspace.src / package)
    for entry in entries:
        if entry.file not in plans:
            continue
        built = shared_headers.precompiled(
            str(tmp_path), plans[entry.file], entry.arguments,
            entry.directory, find_resource_dir())
        assert built is not None, plans[entry.file]
        pch, pch_inputs = built
        alone = parse_unit(file=entry.file, arguments=entry.arguments,
                           directory=entry.directory)
        shared = parse_unit(
            file=entry.file, arguments=entry.arguments + ['-include-pch', pch],
            directory=entry.directory)
        assert cpp.parse_diagnostics(shared) == []
        relative = os.path.relpath(entry.file, package_path)
        assert cpp.extract_facts(
            shared, package_path=package_path, source=relative).to_dict() == \
            cpp.extract_facts(
                alone, package_path=package_path, source=relative).to_dict()
        # the cache's inputs: what the unit read, with the PCH's files
        assert _read(shared) | set(pch_inputs) == _read(alone)


def _read(tu):
    return {os.path.abspath(i.include.name) for i in tu.get_includes()
            if i.include is not None}
