# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Which Python files make which node, read without running anything.

* ROS 1 catkin: scripts installed with ``catkin_install_python(PROGRAMS …)``
  or ``install(PROGRAMS …)`` in ``CMakeLists.txt``, and files in
  ``scripts/`` or ``nodes/`` with a python shebang (``rosrun`` finds them in
  the source space); the executable is the file name.
* ROS 2 ament_python: the ``console_scripts`` entry points of ``setup.py``
  (read with :mod:`ast`) or ``setup.cfg``, ``name = pkg.module:func``; the
  executable is ``name``, the entry function ``func`` of that module.
* ament_cmake (ament_cmake_python): scripts installed with
  ``install(PROGRAMS …)``.
* Any build type: a script nothing installs (a plotting or checking tool
  run as ``python3 script/tool.py``) is still a program of the package
  when it has a python shebang, a ``__main__`` guard and starts ROS
  (``rclpy.init``, ``rospy.init_node``); the executable is the file name
  and the node says it is not installed.

The package's modules (for imports between them) are the Python packages
(directories with ``__init__.py``) at the top of the package and under
``src/``, named from there, and the scripts, each named by its file name
without ``.py``.
"""

import ast
import configparser
from dataclasses import dataclass
from dataclasses import field
import os
import re
from typing import Dict
from typing import List
from typing import Optional

from colcon_rsia import safe_files
from colcon_rsia.frontend.python_api import API_MODULES
from colcon_rsia.package.nodes import cmakelists_text
from colcon_rsia.package.nodes import project_name
import defusedxml.ElementTree as ElementTree

SCRIPT_DIRECTORIES = ('scripts', 'nodes')
# directories whose Python files are not modules of the nodes
SKIPPED_DIRECTORIES = frozenset({
    'test', 'tests', 'launch', 'build', 'install', 'log', 'devel',
    '__pycache__', 'doc', 'docs', 'resource'})
# install() keywords that end a PROGRAMS list
_INSTALL_KEYWORDS = frozenset({
    'DESTINATION', 'PERMISSIONS', 'CONFIGURATIONS', 'COMPONENT', 'RENAME',
    'OPTIONAL', 'EXCLUDE_FROM_ALL', 'FILES', 'DIRECTORY', 'TARGETS',
    'PROGRAMS', 'NAMELINK_SKIP'})


@dataclass
class PythonNode:
    """One Python node of a package before its facts are known."""

    executable: str
    module: str                     # the entry module's dotted name
    path: str                       # its file (absolute)
    function: Optional[str] = None  # console_scripts: the entry function
    installed: bool = True          # False: run from the source tree


@dataclass
class PythonLayout:
    """The Python side of a package."""

    build_type: str
    modules: Dict[str, str] = field(default_factory=dict)  # name -> file
    nodes: List[PythonNode] = field(default_factory=list)
    problems: List[str] = field(default_factory=list)


def build_type(package_path):
    """The package's build type from package.xml (default ``catkin``)."""
    try:
        root = ElementTree.fromstring(safe_files.read_bytes(
            os.path.join(package_path, 'package.xml'),
            roots=[package_path]))
    except (OSError, ElementTree.ParseError, ValueError):
        return 'catkin'
    for export in root.iter('export'):
        for element in export.iter('build_type'):
            if element.text and element.text.strip():
                return element.text.strip()
    return 'catkin'


def is_python_script(path):
    """Whether a file is Python: ``.py``, or a python shebang."""
    return path.endswith('.py') or _has_python_shebang(path)


def find_python_nodes(package_path):
    """Return the :class:`PythonLayout` of a package."""
    package_path = os.path.abspath(package_path)
    layout = PythonLayout(build_type=build_type(package_path))
    layout.modules = _package_modules(package_path)
    scripts = {}
    if layout.build_type == 'ament_python':
        _entry_points(package_path, layout)
    else:
        # ament_cmake_python: a Python package of the CMake package, with
        # the entry points of its own setup.cfg
        for setup_cfg in _cmake_python_setup_cfgs(package_path):
            _entry_points(package_path, layout, setup_cfg)
        for name, path in _installed_programs(package_path):
            if is_python_script(path):
                scripts[path] = name
        if layout.build_type == 'catkin':
            for path in _script_files(package_path):
                scripts.setdefault(path, os.path.basename(path))
    known = set(scripts) | {n.path for n in layout.nodes}
    uninstalled = {
        path: os.path.basename(path)
        for path in _uninstalled_ros_scripts(package_path)
        if path not in known}
    scripts.update(uninstalled)
    for path, executable in sorted(scripts.items()):
        module = script_module_name(path)
        if layout.modules.setdefault(module, path) != path:
            # scripts/foo next to the package foo: the script's directory
            # is not a package, so nothing imports the script by this name
            module = os.path.relpath(path, package_path).replace(os.sep, '/')
            layout.modules[module] = path
        layout.nodes.append(PythonNode(
            executable=executable, module=module, path=path,
            installed=path not in uninstalled))
    names = [n.executable for n in layout.nodes]
    for name in sorted({n for n in names if names.count(n) > 1}):
        layout.problems.append(
            f"executable '{name}' is defined more than once")
    return layout


def script_module_name(path):
    """A script runs as a top-level module named after its file."""
    name = os.path.basename(path)
    return name[:-3] if name.endswith('.py') else name


def _package_modules(package_path):
    modules = {}
    for root in (package_path, os.path.join(package_path, 'src')):
        try:
            entries = sorted(os.listdir(root))
        except OSError:
            continue
        for entry in entries:
            directory = os.path.join(root, entry)
            if entry in SKIPPED_DIRECTORIES or entry.startswith('.') or \
                    not os.path.isfile(os.path.join(directory, '__init__.py')):
                continue
            if entry in API_MODULES:
                # the client library's own package (rospy in ros_comm):
                # its scripts call the API, which the table reads, not its
                # implementation
                continue
            for dirpath, dirnames, filenames in os.walk(directory):
                dirnames[:] = sorted(
                    d for d in dirnames
                    if d not in SKIPPED_DIRECTORIES and not d.startswith('.')
                    and os.path.isfile(os.path.join(dirpath, d, '__init__.py')))
                relative = os.path.relpath(dirpath, root).split(os.sep)
                for filename in sorted(filenames):
                    if not filename.endswith('.py'):
                        continue
                    parts = list(relative)
                    if filename != '__init__.py':
                        parts.append(filename[:-3])
                    modules.setdefault(
                        '.'.join(parts), os.path.join(dirpath, filename))
    # helper modules next to the scripts are importable by them
    for directory in SCRIPT_DIRECTORIES:
        try:
            entries = sorted(os.listdir(os.path.join(package_path, directory)))
        except OSError:
            continue
        for entry in entries:
            path = os.path.join(package_path, directory, entry)
            if entry.endswith('.py') and os.path.isfile(path):
                modules.setdefault(entry[:-3], path)
    return modules


def _script_files(package_path):
    found = []
    for directory in SCRIPT_DIRECTORIES:
        base = os.path.join(package_path, directory)
        try:
            entries = sorted(os.listdir(base))
        except OSError:
            continue
        for entry in entries:
            path = os.path.join(base, entry)
            if os.path.isfile(path) and _has_python_shebang(path):
                found.append(path)
    return found


# a script's own entry: ``if __name__ == '__main__':``
_MAIN_GUARD = re.compile(
    rb'^if\s+__name__\s*==\s*[\'"]__main__[\'"]\s*:', re.MULTILINE)
# it starts ROS itself, so it is a node and not a tool around one
_STARTS_ROS = re.compile(rb'\b(rclpy\.init|rospy\.init_node)\s*\(')
# the guard and the ROS start are looked for in a script's first megabyte
_MAX_SCRIPT_BYTES = 1 << 20


def _uninstalled_ros_scripts(package_path):
    """Python programs anywhere in the package that start a ROS node."""
    found = []
    for dirpath, dirnames, filenames in os.walk(package_path):
        # a Python package's files are modules, not scripts; a package
        # nested in this one has its own scripts
        dirnames[:] = sorted(
            d for d in dirnames
            if d not in SKIPPED_DIRECTORIES and not d.startswith('.') and
            not os.path.isfile(os.path.join(dirpath, d, '__init__.py')) and
            not os.path.exists(os.path.join(dirpath, d, 'package.xml')))
        for filename in sorted(filenames):
            path = os.path.join(dirpath, filename)
            # scripts are `tool.py` or `tool`, never `tool.cpp`
            if not (filename.endswith('.py') or '.' not in filename) or \
                    os.path.islink(path) or not os.path.isfile(path) or \
                    not _has_python_shebang(path):
                continue
            try:
                text = safe_files.read_head(path, _MAX_SCRIPT_BYTES)
            except OSError:
                continue
            if _MAIN_GUARD.search(text) and _STARTS_ROS.search(text):
                found.append(path)
    return found


def _has_python_shebang(path):
    try:
        first = safe_files.read_head(path, 200).split(b'\n')[0]
    except OSError:
        return False
    return first.startswith(b'#!') and b'python' in first


# --- CMakeLists.txt -------------------------------------------------------

_COMMAND = re.compile(
    r'\b(catkin_install_python|install|set)\s*\(([^)]*)\)', re.IGNORECASE)


def _installed_programs(package_path):
    """[(executable, absolute path)] installed as PROGRAMS by CMake."""
    text = cmakelists_text(package_path)
    if text is None:
        return []
    variables = {'PROJECT_NAME': project_name(text)}
    programs = []
    for match in _COMMAND.finditer(text):
        command = match.group(1).lower()
        words = []
        for word in re.findall(r'"[^"]*"|\S+', match.group(2)):
            words.extend(_expand(word.strip('"'), variables))
        if command == 'set':
            if words:
                variables[words[0]] = ' '.join(words[1:])
            continue
        if 'PROGRAMS' not in words:
            continue
        start = words.index('PROGRAMS') + 1
        end = start
        while end < len(words) and words[end] not in _INSTALL_KEYWORDS:
            end += 1
        files = words[start:end]
        rename = None
        if 'RENAME' in words[end:]:
            position = words.index('RENAME', end) + 1
            if position < len(words) and len(files) == 1:
                rename = words[position]
        for file in files:
            path = os.path.normpath(os.path.join(package_path, file))
            if os.path.isfile(path):
                programs.append((rename or os.path.basename(path), path))
    return programs


def _expand(word, variables):
    expanded = re.sub(
        r'\$\{(\w+)\}', lambda m: variables.get(m.group(1), ''), word)
    return expanded.split()


# --- setup.py / setup.cfg ---------------------------------------------------

def _entry_points(package_path, layout, setup_cfg=None):
    """The nodes of console_scripts: setup.py's, else setup.cfg's."""
    if setup_cfg is None:
        layout.problems += safe_files.unreadable_files(
            package_path, ['setup.py', 'setup.cfg'])
        specs = _setup_py_console_scripts(package_path)
        if specs is None:
            specs = _setup_cfg_console_scripts(package_path)
    else:
        specs = _setup_cfg_console_scripts(package_path, setup_cfg)
    for spec in specs or []:
        name, _, target = spec.partition('=')
        name = name.strip()
        target = re.sub(r'\[.*\]', '', target).strip()
        module, _, function = target.partition(':')
        module, function = module.strip(), function.strip()
        if not name or not module or not function:
            layout.problems.append(
                f"console_scripts entry '{spec}' is not 'name = module:func'")
            continue
        path = layout.modules.get(module)
        if path is None:
            layout.problems.append(
                f"console_scripts '{name}': module '{module}' not found in "
                'the package; not analysed')
            continue
        layout.nodes.append(PythonNode(
            executable=name, module=module, path=path, function=function))


def _setup_py_console_scripts(package_path):
    """The console_scripts of setup.py, or None when it names none."""
    try:
        tree = ast.parse(safe_files.read_bytes(
            os.path.join(package_path, 'setup.py'), roots=[package_path]))
    except (OSError, SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    constants = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and \
                isinstance(node.targets[0], ast.Name):
            value = _static(node.value, constants)
            if value is not None:
                constants[node.targets[0].id] = value
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        name = func.id if isinstance(func, ast.Name) else \
            getattr(func, 'attr', None)
        if name != 'setup':
            continue
        for keyword in node.keywords:
            if keyword.arg != 'entry_points':
                continue
            entry_points = _static(keyword.value, constants)
            if isinstance(entry_points, dict):
                scripts = entry_points.get('console_scripts')
                if isinstance(scripts, str):
                    scripts = scripts.splitlines()
                if isinstance(scripts, list):
                    return [s for s in scripts
                            if isinstance(s, str) and s.strip()]
    return None


def _static(node, constants):
    """The value of a literal-like expression (strings, lists, dicts)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.Name):
        return constants.get(node.id)
    if isinstance(node, (ast.List, ast.Tuple)):
        values = [_static(e, constants) for e in node.elts]
        return values if None not in values else None
    if isinstance(node, ast.Dict):
        result = {}
        for key, value in zip(node.keys, node.values):
            key = _static(key, constants) if key is not None else None
            if isinstance(key, str):
                result[key] = _static(value, constants)
        return result
    if isinstance(node, ast.JoinedStr):
        parts = []
        for value in node.values:
            if isinstance(value, ast.FormattedValue):
                value = value.value
            part = _static(value, constants)
            if not isinstance(part, str):
                return None
            parts.append(part)
        return ''.join(parts)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left = _static(node.left, constants)
        right = _static(node.right, constants)
        if isinstance(left, str) and isinstance(right, str):
            return left + right
        if isinstance(left, list) and isinstance(right, list):
            return left + right
    return None


_INSTALL_PYTHON_PACKAGE = re.compile(
    r'\bament_python_install_package\s*\(([^)]*)\)', re.IGNORECASE)


def _cmake_python_setup_cfgs(package_path):
    """The setup.cfg files ament_python_install_package() names.

    ``ament_python_install_package(pkg SETUP_CFG pkg/setup.cfg ...)``
    installs the package's Python package with that file's entry points
    as executables (``${PROJECT_NAME}``: the name `project()` gives).
    """
    try:
        text = safe_files.read_text(
            os.path.join(package_path, 'CMakeLists.txt'),
            roots=[package_path], errors='replace')
    except OSError:
        return []
    project = re.search(r'\bproject\s*\(\s*([\w-]+)', text, re.IGNORECASE)
    found = []
    for call in _INSTALL_PYTHON_PACKAGE.finditer(text):
        words = call.group(1).split()
        if 'SETUP_CFG' in words[:-1] and project:
            name = words[words.index('SETUP_CFG') + 1]
            found.append(name.replace('${PROJECT_NAME}', project.group(1)))
    return found


def _setup_cfg_console_scripts(package_path, setup_cfg='setup.cfg'):
    parser = configparser.ConfigParser(interpolation=None)
    try:
        parser.read_string(safe_files.read_bytes(
            os.path.join(package_path, setup_cfg),
            roots=[package_path]).decode('utf-8'))
        value = parser.get('options.entry_points', 'console_scripts',
                           fallback='')
    except (configparser.Error, OSError, UnicodeDecodeError):
        return None
    return [line.strip() for line in value.splitlines() if line.strip()]
