# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Which sources make which node.

C++ executables come from the CMake file-API codemodel that colcon-cmake asks
CMake for (``build/<pkg>/.cmake/api/v1/reply``); before a build, from the
codemodel of our own configure (see
:mod:`colcon_rsia.package.cmake_configure`); when CMake cannot be asked,
from ``add_executable`` in ``CMakeLists.txt``. Nodelets come from the plugin XML exported in
``package.xml`` and the ``PLUGINLIB_EXPORT_CLASS`` lines of the sources.
"""

import os
import re

from colcon_rsia import safe_files
from colcon_rsia.frontend.compile_db import COMPILE_DB_FILENAME
from colcon_rsia.package.cmake_configure import configure_package
from colcon_rsia.package.cmake_configure import executables_from_codemodel
from colcon_rsia.package.cmake_configure import is_cxx_source
from colcon_rsia.package.cmake_configure import strip_comments
import defusedxml.ElementTree as ElementTree

NODELET_BASE_CLASS = 'nodelet::Nodelet'


def find_executables(*, package_path, build_base, diagnostics=None,
                     read_by=None):
    """Return {executable name: [absolute source paths]} of a package.

    From the codemodel of the package's build, else from our own configure
    of the package (:mod:`colcon_rsia.package.cmake_configure`), else, when
    CMake cannot be asked, from reading ``CMakeLists.txt`` here.

    :param diagnostics: a list that receives why CMake could not be asked
      when ``CMakeLists.txt`` is read here
    :param read_by: a list that receives who read the CMake code: CMAKE,
      or TEXT_READER (whose targets are those of ``add_executable`` only)
    """
    read_by = [] if read_by is None else read_by
    executables = executables_from_codemodel(build_base)
    if executables is not None:
        read_by.append(CMAKE)
        return executables
    configured = configure_package(package_path, build_base)
    if configured.executables is not None:
        read_by.append(CMAKE)
        return configured.executables
    if configured.problem and diagnostics is not None:
        diagnostics.append(configured.problem)
    read_by.append(TEXT_READER)
    return _executables_from_cmakelists(package_path)


CMAKE = 'cmake'
TEXT_READER = 'text'
# a command call without nested parentheses: name(arguments)
_COMMAND_CALL = re.compile(r'\b(\w+)\s*\(([^()]*)\)')


def target_naming(package_path, source):
    """The target a command of the CMake code may build `source` into.

    For the text reader, which knows no command but ``add_executable``:
    the first argument of a command that names the source's file
    (``google_binary(cartographer_node SRCS node_main.cc)``, a command
    an unknown CMake module defines; a target-making command takes the
    target's name first), or None when no command names the file.
    """
    name = os.path.basename(source)
    # the CMakeLists.txt of its directory and of those above it, up to the
    # package's (add_subdirectory(): a source is named where it lies)
    texts = [read_cmakelists(package_path)]
    directory = os.path.dirname(os.path.abspath(source))
    root = os.path.abspath(package_path)
    while directory.startswith(root + os.sep):
        texts.append(cmakelists_text(directory) or '')
        directory = os.path.dirname(directory)
    for text in texts:
        for match in _COMMAND_CALL.finditer(text):
            words = match.group(2).split()
            if any(os.path.basename(w.strip('"')) == name
                   for w in words[1:]) and \
                    re.fullmatch(r'[A-Za-z_][\w.+-]*', words[0]):
                return words[0]
    return None


def skipped_executable(executable, sources, *, package_path, build_base,
                       parsed, skipped_directories):
    """Why an executable none of whose sources was analysed is skipped.

    :param parsed: the files the analysis parsed (a failed parse said why
      in a diagnostic of its own)
    :param skipped_directories: the directories whose sources an unbuilt
      package's analysis leaves out
    """
    if any(s in parsed for s in sources):
        return (f"executable '{executable}': none of its sources could be "
                'analysed (see above); skipped')
    existing = [os.path.relpath(s, package_path) for s in sources
                if os.path.lexists(s)]
    if not existing:
        return (f"executable '{executable}': none of its sources is in the "
                'compile database; skipped')
    shown = ', '.join(existing[:3]) + (', …' if len(existing) > 3 else '')
    if os.path.isfile(os.path.join(build_base, COMPILE_DB_FILENAME)):
        why = 'not in the compile database'
    else:
        directory = next((d for d in existing[0].split(os.sep)[:-1]
                          if d in skipped_directories), None)
        why = f'under {directory}/, whose sources are not analysed' \
            if directory else 'not among the sources analysed'
    return (f"executable '{executable}': not analysed: its sources "
            f'({shown}) are {why}; skipped')


def _configured_registrations(package_path, build_base):
    """The component registrations our configure recorded, or None.

    None for a built package (its CMakeLists.txt is read, as before) and
    when CMake could not be asked.
    """
    if build_base is None or \
            executables_from_codemodel(build_base) is not None:
        return None
    configured = configure_package(package_path, build_base)
    if configured.executables is None:
        return None
    return configured.registrations


_ADD_EXECUTABLE = re.compile(r'add_executable\s*\(([^)]*)\)', re.IGNORECASE)
_DEFINITION = re.compile(
    r'^[ \t]*(function|macro)\s*\(\s*(\w+)([^)]*)\)(.*?)'
    r'^[ \t]*end\1\s*\([^)]*\)', re.IGNORECASE | re.MULTILINE | re.DOTALL)
_SET = re.compile(r'^[ \t]*set\s*\(\s*(\w+)\s+([^)\s]+)\s*\)',
                  re.IGNORECASE | re.MULTILINE)


def cmakelists_text(package_path):
    """The package's CMakeLists.txt without its comments, or None."""
    try:
        return strip_comments(safe_files.read_text(
            os.path.join(package_path, 'CMakeLists.txt'),
            roots=[package_path]))
    except OSError:
        return None


def project_name(text):
    """The name given to ``project()`` in CMake text ('' when none)."""
    project = re.search(r'\bproject\s*\(\s*([\w-]+)', text, re.IGNORECASE)
    return project.group(1) if project else ''


def read_cmakelists(package_path):
    """The package's CMakeLists.txt as the commands that run, or ''.

    Comments are dropped, ``${PROJECT_NAME}`` and single-value ``set()``
    variables substituted, and calls of the file's own ``function()`` and
    ``macro()`` expanded with their arguments (packages wrap
    ``add_executable`` in helpers: ``custom_executable(topics talker)``).
    """
    text = cmakelists_text(package_path)
    if text is None:
        return ''
    definitions = {}
    for match in _DEFINITION.finditer(text):
        definitions[match.group(2).lower()] = (
            match.group(3).split(), match.group(4))
    text = _DEFINITION.sub('', text)
    # helpers calling helpers: a few rounds reach a fixed point
    for _ in range(3):
        text = _expand_calls(text, definitions)
    variables = {'PROJECT_NAME': project_name(text)}
    for match in _SET.finditer(text):
        variables.setdefault(match.group(1), match.group(2).strip('"'))
    return _substitute(text, variables)


def _expand_calls(text, definitions):
    if not definitions:
        return text
    call = re.compile(
        r'\b(' + '|'.join(re.escape(n) for n in definitions) +
        r')\s*\(([^)]*)\)', re.IGNORECASE)

    def expand(match):
        params, body = definitions[match.group(1).lower()]
        arguments = [a.strip('"') for a in match.group(2).split()]
        values = {'ARGN': ' '.join(arguments[len(params):]),
                  'ARGV': ' '.join(arguments)}
        values.update(zip(params, arguments))
        values.update((f'ARGV{i}', a) for i, a in enumerate(arguments))
        return _substitute(body, values)
    return call.sub(expand, text)


def _executables_from_cmakelists(package_path):
    text = read_cmakelists(package_path)
    executables = {}
    for match in _ADD_EXECUTABLE.finditer(text):
        words = match.group(1).split()
        if not words or words[0] in ('IMPORTED', 'ALIAS') or \
                '${' in words[0]:
            continue
        sources = [
            os.path.normpath(os.path.join(package_path, w))
            for w in words[1:] if is_cxx_source(w)]
        if sources:
            executables[words[0]] = sources
    return executables


def _substitute(word, variables):
    return re.sub(
        r'\$\{(\w+)\}', lambda m: variables.get(m.group(1), m.group(0)), word)


def find_nodelets(*, package_path, exported_classes):
    """Return {plugin name: class name} of the package's nodelets.

    :param exported_classes: (class, base class) pairs found in the sources
    """
    return {name: class_name for name, (class_name, _) in _plugins(
        package_path, exported_classes,
        lambda base: base == NODELET_BASE_CLASS).items()}


def find_plugins(*, package_path, exported_classes):
    """Return {plugin name: (class name, base class)} of other plugins.

    The pluginlib classes that are neither nodelets nor components: a
    controller, a planner, a costmap layer... (see
    :mod:`colcon_rsia.package.plugin_hosts` for their hosts).
    """
    return _plugins(
        package_path, exported_classes,
        lambda base: base not in (NODELET_BASE_CLASS, COMPONENT_BASE_CLASS))


def _plugins(package_path, exported_classes, wanted):
    """{plugin name: (class, base)} of the wanted bases, XML and code.

    The plugin description XML names a class (``pkg/Name``); a class
    exported in code but missing from the XML still loads: it is named
    by its class so that it is not lost.
    """
    declared = {}
    for name, class_type, base in _described_classes(package_path):
        if wanted(base):
            declared[name] = (class_type, base)
    known = {class_type for class_type, _ in declared.values()}
    for class_name, base in sorted(
            (c.lstrip(':'), b.lstrip(':')) for c, b in exported_classes):
        if wanted(base) and class_name not in known:
            declared[class_name] = (class_name, base)
            known.add(class_name)
    return declared


def _described_classes(package_path):
    """(name, class, base) of every class in the package's plugin XML."""
    classes = []
    for xml_path in _plugin_xml_files(package_path):
        try:
            root = ElementTree.fromstring(safe_files.read_bytes(
                xml_path, roots=[package_path]))
        except (OSError, ElementTree.ParseError, ValueError):
            continue
        for element in root.iter('class'):
            base = element.get('base_class_type', '').lstrip(':')
            class_type = element.get('type', '').lstrip(':')
            if class_type:
                classes.append(
                    (element.get('name') or class_type, class_type, base))
    return classes


# ROS 2 packages export their plugin XML from CMake, not package.xml
_EXPORT_DESCRIPTION = re.compile(
    r'pluginlib_export_plugin_description_file\s*\(\s*\S+\s+"?([^")\s]+)',
    re.IGNORECASE)


def _plugin_xml_files(package_path):
    files = []
    for match in _EXPORT_DESCRIPTION.finditer(read_cmakelists(package_path)):
        files.append(os.path.join(package_path, match.group(1)))
    manifest = os.path.join(package_path, 'package.xml')
    try:
        root = ElementTree.fromstring(safe_files.read_bytes(
            manifest, roots=[package_path]))
    except (OSError, ElementTree.ParseError, ValueError):
        return files
    for export in root.iter('export'):
        for element in export:
            plugin = element.get('plugin')
            if plugin:
                files.append(os.path.join(
                    package_path, plugin.replace('${prefix}', '').lstrip('/')))
    return sorted(set(files))


COMPONENT_BASE_CLASS = 'rclcpp::Node'
_REGISTER_COMPONENT = re.compile(
    r'rclcpp_components_register_nodes?\s*\(([^)]*)\)', re.IGNORECASE)


def find_components(*, package_path, exported_classes, build_base=None):
    """Return {node name: class name} of the package's ROS 2 components.

    A component is registered with ``RCLCPP_COMPONENTS_REGISTER_NODE`` in
    its source and/or ``rclcpp_components_register_node(target PLUGIN
    "ns::Class" EXECUTABLE name)`` in CMakeLists.txt; it is named after the
    executable when one is given, else after its class. The registrations
    are those our configure of an unbuilt package recorded (with
    ``build_base``), else those read in CMakeLists.txt.
    """
    classes = {c.lstrip(':') for c, base in exported_classes
               if base == COMPONENT_BASE_CLASS}
    registrations = _configured_registrations(package_path, build_base)
    if registrations is None:
        registrations = _registrations_in_cmakelists(package_path)
    executables = {}
    for kind, *names in registrations:
        if kind == 'nodes':
            # the plural form lists plugin classes, no executables
            classes.update(n.lstrip(':') for n in names if n)
        elif names and names[0]:
            plugin = names[0].lstrip(':')
            classes.add(plugin)
            if len(names) > 1 and names[1]:
                executables[plugin] = names[1]
    shorts = [c.split('::')[-1] for c in classes if c not in executables]
    components = {}
    for class_name in sorted(classes):
        name = executables.get(class_name)
        if name is None:
            short = class_name.split('::')[-1]
            # two namespaces' Talker: the qualified names tell them apart
            name = short if shorts.count(short) == 1 else class_name
        components[name] = class_name
    return components


def _registrations_in_cmakelists(package_path):
    """('node', plugin, executable) and ('nodes', class) read in the text."""
    registrations = []
    for match in _REGISTER_COMPONENT.finditer(read_cmakelists(package_path)):
        words = [w.strip('"') for w in match.group(1).split()]
        if any('${' in w for w in words):
            continue  # a name we could not work out
        if match.group(0).lower().startswith(
                'rclcpp_components_register_nodes'):
            registrations += [('nodes', w) for w in words[1:] if '::' in w]
            continue
        plugin = executable = ''
        for keyword, value in zip(words, words[1:]):
            if keyword == 'PLUGIN':
                plugin = value
            elif keyword == 'EXECUTABLE':
                executable = value
        registrations.append(('node', plugin, executable))
    return registrations
