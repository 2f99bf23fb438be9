# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The plugins a C++ unit registers: pluginlib, components, BT nodes.

Read from the main file's text with the registration macros, not from the
AST (see the comment on :data:`EXPORT_MACRO`).
"""

import re

# plugin registrations, read from the source text: a detailed processing
# record would show them as macro instantiations, but it triples the number
# of top-level cursors (every macro of every header) and so the walk time
EXPORT_MACRO = re.compile(
    r'\b(?:PLUGINLIB_EXPORT_CLASS|CLASS_LOADER_REGISTER_CLASS)\s*\(\s*'
    r'([\w:]+(?:\s*<[^;()]*?>)?)\s*,\s*([\w:]+(?:\s*<[^;()]*>)?)\s*\)')
COMPONENT_MACRO = re.compile(
    r'\bRCLCPP_COMPONENTS_REGISTER_NODE\s*\(\s*([\w:]+)\s*\)')
# the base recorded for a registered ROS 2 component
COMPONENT_BASE = 'rclcpp::Node'
# behavior-tree nodes a plugin library registers for a BT executor
# (navigation2's bt_navigator): `BT_REGISTER_NODES(factory) { ...
# factory.registerNodeType<ns::Class>("Name"); }`
BT_REGISTRATION = re.compile(r'\bBT_REGISTER_NODES\s*\(\s*(\w+)\s*\)')
BT_NODE_TYPE = re.compile(r'\bregisterNodeType\s*<\s*([\w:]+)\s*>')
# the base recorded for them (the table's key: plugin_hosts.py)
BT_NODE_BASE = 'BT::TreeNode'
# Gazebo plugins, which gzserver loads (gazebo/common/Plugin.hh):
# `GZ_REGISTER_MODEL_PLUGIN(Class)`, written inside the class's namespace
GAZEBO_BASES = {
    'MODEL': 'gazebo::ModelPlugin',
    'SENSOR': 'gazebo::SensorPlugin',
    'WORLD': 'gazebo::WorldPlugin',
    'SYSTEM': 'gazebo::SystemPlugin',
}
_GAZEBO_MACRO = r'\bGZ_REGISTER_(MODEL|SENSOR|WORLD|SYSTEM)_PLUGIN\s*\(\s*([\w:]+)\s*\)'
# what the macros expand to, written by hand: the entry point gzserver calls,
# `gazebo::SensorPlugin * RegisterPlugin() { return new Class(); }` (up to
# the opening brace of its body, which is a scope)
_GAZEBO_ENTRY = (
    r'\b(?:gazebo\s*::\s*)?(Model|Sensor|World|System)Plugin\s*\*\s*'
    r'RegisterPlugin\s*\(\s*(?:void\s*)?\)\s*\{[^{}]*?\bnew\s+([\w:]+)')
# what decides the namespace a macro is written in: comments and literals
# (skipped), namespace openings, other braces, the macro itself
_SCOPES = re.compile(
    r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\''
    r'|\bnamespace\s+((?:\w+\s*::\s*)*\w+)\s*\{|\bnamespace\s*\{|'
    + _GAZEBO_ENTRY + r'|\{|\}|' + _GAZEBO_MACRO, re.S)


def plugin_exports(main_file):
    """[class, base] of each plugin a unit's main file registers."""
    exports = []
    try:
        with open(main_file, encoding='utf-8', errors='replace') as h:
            text = h.read()
    except OSError:
        return exports
    for match in EXPORT_MACRO.finditer(text):
        exports.append(
            [match.group(1).lstrip(':'), match.group(2).lstrip(':')])
    for match in COMPONENT_MACRO.finditer(text):
        exports.append([match.group(1).lstrip(':'), COMPONENT_BASE])
    registration = BT_REGISTRATION.search(text)
    if registration is not None:
        for match in BT_NODE_TYPE.finditer(text, registration.end()):
            exports.append([match.group(1).lstrip(':'), BT_NODE_BASE])
    if 'GZ_REGISTER_' in text or 'RegisterPlugin' in text:
        exports += gazebo_exports(text)
    return exports


def gazebo_exports(text):
    """[class, base] of the Gazebo plugins a source registers.

    With a ``GZ_REGISTER_*_PLUGIN`` macro, or with what it expands to
    written by hand (the ``RegisterPlugin`` entry point). Either names the
    class as its namespace sees it: the namespaces it is written in
    qualify it.
    """
    exports = []
    scopes = []  # a namespace's name, or None for any other brace
    for match in _SCOPES.finditer(text):
        token = match.group(0)
        # (groups: 1 a namespace; 2, 3 the entry point; 4, 5 the macro)
        entry = match.group(3) is not None
        kind, class_name = match.group(2, 3) if entry else match.group(4, 5)
        if class_name:
            if not class_name.startswith('::'):
                class_name = '::'.join(
                    [s for s in scopes if s] + [class_name])
            exports.append(
                [class_name.lstrip(':'), GAZEBO_BASES[kind.upper()]])
            if entry:
                scopes.append(None)  # (the entry point's body)
        elif token.startswith('namespace'):
            name = match.group(1)
            scopes.append(re.sub(r'\s+', '', name) if name else None)
        elif token == '{':
            scopes.append(None)
        elif token == '}' and scopes:
            scopes.pop()
    return exports
