# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The layout is the architecture: layers, no import cycles.

Build time (``package``, reading code through ``frontend``) and query time
(``system``, reading launch files through ``launch``) meet only in the
package summary (``summary``: its data classes and files), which imports
neither; ``system`` and ``report`` import nothing of ``package``. The
colcon glue (``verb``, ``subverb``, ``event_handler``), ``render`` (the
output of the queries) and ``report`` sit on top.
"""

import ast
from pathlib import Path
import subprocess
import sys

import pytest

PACKAGE_DIR = Path(__file__).resolve().parents[2] / 'colcon_rsia'

# which layers a layer may import (besides itself and colcon_rsia's
# __version__); the summary contract (summary) is the one thing both
# phases share
ALLOWED = {
    'summary': {'safe_files'},
    'environment_variables': set(),
    # reading files of an untrusted workspace: for every layer
    'safe_files': {'environment_variables'},
    # the arithmetic of Python expressions: for both readers of Python
    'python_arithmetic': set(),
    'frontend': {'summary', 'environment_variables', 'safe_files',
                 'python_arithmetic'},
    'launch': {'safe_files', 'python_arithmetic'},
    'package': {'summary', 'frontend', 'environment_variables', 'safe_files'},
    'system': {'summary', 'launch', 'safe_files'},
    # the output of the queries: from system's results, never from the
    # build-time code (a result it renders is a document of its own)
    'render': {'summary', 'system', 'safe_files'},
    'report': {'summary', 'system', 'render', 'safe_files'},
    'event_handler': {'package', 'render', 'safe_files'},
    'subverb': {'summary', 'package', 'system', 'render', 'report',
                'environment_variables', 'safe_files'},
    'verb': {'subverb'},
}


def _modules():
    modules = {}
    for path in sorted(PACKAGE_DIR.rglob('*.py')):
        parts = list(path.relative_to(PACKAGE_DIR.parent).with_suffix('').parts)
        if parts[-1] == '__init__':
            parts = parts[:-1]
        modules['.'.join(parts)] = path
    return modules


MODULES = _modules()


def _imports(path):
    """colcon_rsia modules a file imports, anywhere in it (also lazily)."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.ImportFrom) and node.level == 0 and \
                node.module.split('.')[0] == 'colcon_rsia':
            for alias in node.names:
                submodule = f'{node.module}.{alias.name}'
                found.add(submodule if submodule in MODULES else node.module)
        elif isinstance(node, ast.Import):
            found.update(
                alias.name for alias in node.names
                if alias.name.split('.')[0] == 'colcon_rsia')
    return found


def _packages_of(module):
    parts = module.split('.')
    return {'.'.join(parts[:i]) for i in range(1, len(parts))}


def _import_graph():
    graph = {}
    for module, path in MODULES.items():
        # its own packages are being imported when a module is: never a
        # cycle unless the module names them itself
        own_packages = _packages_of(module)
        targets = set()
        for target in _imports(path):
            # importing a.b.c runs a/__init__ and a/b/__init__ first
            targets.add(target)
            targets.update(_packages_of(target) - own_packages)
        graph[module] = targets - {module, 'colcon_rsia'}
    return graph


def _cycles(graph):
    """One cycle through each strongly connected part of the graph."""
    cycles, state = [], {}

    def visit(module, stack):
        state[module] = 'open'
        stack.append(module)
        for target in sorted(graph.get(module, ())):
            if state.get(target) == 'open':
                cycles.append(stack[stack.index(target):] + [target])
            elif target not in state:
                visit(target, stack)
        stack.pop()
        state[module] = 'done'

    for module in sorted(graph):
        if module not in state:
            visit(module, [])
    return cycles


def test_cycle_finder_finds_a_cycle():
    graph = {'a': {'b'}, 'b': {'c'}, 'c': {'a'}, 'd': {'a'}}
    assert _cycles(graph) == [['a', 'b', 'c', 'a']]
    assert _cycles({'a': {'b'}, 'b': set()}) == []


def test_no_import_cycles():
    # lazy imports inside functions count: they only hide a cycle
    assert _cycles(_import_graph()) == []


def _reachable(graph, module):
    """The modules a module imports, directly or through others."""
    seen, stack = set(), [module]
    while stack:
        for target in graph.get(stack.pop(), ()):
            if target not in seen:
                seen.add(target)
                stack.append(target)
    return seen


LAUNCH = 'colcon_rsia.launch'
# the readers of ROS 2 launch files and what only they use; the executor
# is handed them as a table and runs what they build
ROS2_READERS = {f'{LAUNCH}.ros2'} | {
    m for m in MODULES if m.startswith(f'{LAUNCH}.python_launch')}


def test_launch_executor_and_readers_do_not_import_each_other():
    graph = _import_graph()
    executor = f'{LAUNCH}.ros2_executor'
    assert _reachable(graph, executor) & ROS2_READERS == set()
    for reader in ROS2_READERS:
        assert executor not in _reachable(graph, reader), reader


def test_launch_modules_import_no_launch_entry():
    # launch/__init__ (load_launch) picks the readers and the executor:
    # a module below it that imported it would make a cycle through it
    graph = _import_graph()
    wrong = [m for m in MODULES if m.startswith(f'{LAUNCH}.')
             and LAUNCH in graph[m]]
    assert wrong == []


def test_launch_notes_is_the_lowest_launch_module():
    # every launch module may use shorten/unique without a cycle
    assert _imports(MODULES[f'{LAUNCH}.notes']) == set()


def _layer(module):
    parts = module.split('.')[1:]
    return parts[0] if parts else 'colcon_rsia'


def test_layers():
    wrong = []
    for module, path in MODULES.items():
        targets = _imports(path) - {module}
        layer = _layer(module)
        for target in targets:
            target_layer = _layer(target)
            if target_layer == 'colcon_rsia':
                continue
            allowed = ALLOWED[layer] | {layer}
            if target_layer not in allowed:
                wrong.append(f'{module} imports {target}')
    assert wrong == []


def test_model_mode_stands_apart_from_the_walk():
    # the model mode prepares a unit's arguments before it is parsed and
    # repairs it from the parse's diagnostics: it reads text and those
    # diagnostics (frontend.cpp.parse), never the walk of the C++ front end
    # (which may use it only through its constants)
    model_mode = 'colcon_rsia.frontend.cpp.model_mode'
    diagnostics = 'colcon_rsia.frontend.cpp.parse'
    wrong = []
    for module, path in MODULES.items():
        if module != model_mode and not module.startswith(model_mode + '.'):
            continue
        for target in _imports(path):
            if target.startswith('colcon_rsia.frontend.cpp') and not (
                    target in (model_mode, diagnostics) or
                    target.startswith(model_mode + '.')):
                wrong.append(f'{module} imports {target}')
    assert wrong == []


def test_every_layer_is_known():
    assert {_layer(m) for m in MODULES} - {'colcon_rsia'} <= set(ALLOWED)


@pytest.mark.parametrize('module', sorted(MODULES))
def test_imports_on_its_own(module):
    # a fresh interpreter: the order other tests imported modules in
    # cannot hide a cycle or a missing import
    result = subprocess.run(
        [sys.executable, '-c', f'import {module}'],
        capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr


def test_colcon_calls_do_not_import_heavy_modules():
    # every colcon call (--help, completion, other verbs) loads the rsia
    # verb and its subverbs: networkx, libclang and the analysis load
    # only when a subverb runs
    code = (
        'import sys\n'
        'from colcon_core.command import main\n'
        'try:\n'
        '    main(argv=["rsia", "impact", "--help"])\n'
        'except SystemExit:\n'
        '    pass\n'
        'print(sorted(m for m in sys.modules if m.split(".")[0] in '
        '("networkx", "clang") or m.startswith("colcon_rsia.package.")))\n')
    result = subprocess.run(
        [sys.executable, '-c', code], capture_output=True, text=True,
        timeout=120)
    assert result.returncode == 0, result.stderr
    assert 'usage:' in result.stdout
    assert result.stdout.strip().splitlines()[-1] == '[]'


CPP = 'colcon_rsia.frontend.cpp'
# the C++ walker's helpers: given what they use, never the walker
WALKER_HELPERS = ('roles', 'hosted', 'clocks', 'wrappers', 'strings',
                  'callbacks', 'questions')


def _walker_references(path):
    """Where a module names `walker` (a variable, attribute, parameter)."""
    found = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        name = node.id if isinstance(node, ast.Name) else \
            node.attr if isinstance(node, ast.Attribute) else \
            node.arg if isinstance(node, ast.arg) else None
        if name is not None and name.lstrip('_') == 'walker':
            found.append(f'{path.name}:{node.lineno}')
    return found


def test_walker_reference_finder_finds_one(tmp_path):
    path = tmp_path / 'helper.py'
    path.write_text(
        'class H:\n'
        '    def __init__(self, walker):\n'
        '        self._walker = walker\n')
    assert _walker_references(path) == [
        'helper.py:2', 'helper.py:3', 'helper.py:3']


def test_cpp_walker_helpers_get_what_they_use_not_the_walker():
    # the walker hands its helpers the facts, the walk's Places and the
    # functions they call (questions.py): a helper holding the walker, or
    # importing it, could reach any of its state
    wrong = []
    for helper in WALKER_HELPERS:
        path = MODULES[f'{CPP}.{helper}']
        wrong.extend(_walker_references(path))
        if f'{CPP}.walker' in _imports(path):
            wrong.append(f'{path.name} imports walker')
    assert wrong == []


def test_cpp_walker_mixes_in_no_helper():
    # its helpers are objects it builds, not base classes of its own
    tree = ast.parse(MODULES[f'{CPP}.walker'].read_text())
    bases = [(node.name, len(node.bases)) for node in ast.walk(tree)
             if isinstance(node, ast.ClassDef) and node.bases]
    assert bases == []


FRONTEND = PACKAGE_DIR / 'frontend'


def _fact_classes():
    """The classes of frontend/facts.py."""
    tree = ast.parse((FRONTEND / 'facts.py').read_text())
    return {node.name for node in tree.body if isinstance(node, ast.ClassDef)}


def _fact_constructions(path, classes):
    """Where a module calls one of `classes` (by name or as facts.X)."""
    found = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        name = func.id if isinstance(func, ast.Name) else \
            func.attr if isinstance(func, ast.Attribute) else None
        if name in classes:
            found.append(f'{path.name}:{node.lineno} {name}')
    return found


def test_fact_construction_finder_finds_one(tmp_path):
    path = tmp_path / 'roles.py'
    path.write_text(
        'from colcon_rsia.frontend import facts\n'
        'from colcon_rsia.frontend.facts import TimerFact\n'
        'isinstance(x, TimerFact)\n'
        'a = TimerFact(function=None)\n'
        'b = facts.PublishSite()\n')
    assert _fact_constructions(path, _fact_classes()) == [
        'roles.py:4 TimerFact', 'roles.py:5 PublishSite']


def test_front_ends_make_facts_through_the_fact_builder():
    # one place makes facts (frontend/fact_builder.py): the front ends
    # say what a call's arguments mean, never how a fact is built
    classes = _fact_classes()
    assert {'PublisherFact', 'TimerFact', 'Call', 'TuFacts'} <= classes
    wrong = []
    for front_end in ('cpp', 'python'):
        for path in sorted((FRONTEND / front_end).rglob('*.py')):
            wrong.extend(_fact_constructions(path, classes))
    assert wrong == []


def test_no_module_passes_800_lines():
    # a module past that holds more than one idea: split it (the layout
    # shows the architecture only while each room stays small)
    long = {module: lines for module, path in MODULES.items()
            if (lines := len(path.read_text().splitlines())) > 800}
    assert long == {}


def test_no_test_file_passes_800_lines():
    # the same for the tests: a file past that holds more than one topic
    tests = PACKAGE_DIR.parent / 'tests'
    long = {str(path.relative_to(tests)): lines
            for path in sorted(tests.rglob('*.py'))
            if (lines := len(path.read_text().splitlines())) > 800}
    assert long == {}
