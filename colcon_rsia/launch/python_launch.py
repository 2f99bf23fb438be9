# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""ROS 2 Python launch files, read with the stdlib ``ast`` (never run).

A small interpreter walks ``generate_launch_description()`` (and the module
functions it calls) over a subset of Python: assignments, lists, dicts,
tuples, f-strings, arithmetic on known values, ``if`` on known values,
``for`` over known sequences, and the launch / launch_ros API, which builds
the actions of :mod:`colcon_rsia.launch.ir`. Module-level code other than
imports, constants and definitions is never interpreted. Calls to anything
else give an unknown value with a note; an ``if`` whose condition is not
known runs both branches and marks what they create; a loop over an unknown
sequence runs its body once and marks what it creates.

Here: the entry point and the module level. The interpreter is
:mod:`colcon_rsia.launch.python_launch_interpreter`, the launch API it
knows :mod:`colcon_rsia.launch.python_launch_api`.
"""

import ast

from colcon_rsia.launch.ir import UnknownValue
from colcon_rsia.launch.model import LaunchError
from colcon_rsia.launch.python_launch_interpreter import Interpreter
from colcon_rsia.launch.python_launch_values import BudgetExceeded
from colcon_rsia.launch.python_launch_values import Frame
from colcon_rsia.launch.python_launch_values import Function
from colcon_rsia.launch.python_launch_values import LaunchDescription


def read_python_launch(path, text, loader, root=None):
    """The ROS 2 actions of a Python launch file.

    :param root: not used (an XML reader's argument; every reader takes
      the same)
    :raises LaunchError: when the file is not valid Python
    """
    try:
        tree = ast.parse(text, filename=path)
    except SyntaxError as e:
        raise LaunchError(f'{path}: not valid Python (line {e.lineno}: '
                          f'{e.msg}).')
    except (ValueError, RecursionError, MemoryError) as e:
        raise LaunchError(f'{path}: cannot be parsed as Python '
                          f'({type(e).__name__}).')
    return _launch_description(Interpreter(path, loader), tree)


def _launch_description(interp, tree):
    """The entities the file's generate_launch_description returns."""
    try:
        _read_module(interp, tree)
        function = interp.globals.get('generate_launch_description')
        if not isinstance(function, Function):
            interp.loader.note(f'{interp.path}: no generate_launch_'
                               'description() function; nothing launched')
            return []
        node = function.node
        value = interp.call_function(function, [], {}, node)
    except BudgetExceeded:
        interp.loader.note(f'{interp.path}: the launch file takes too many '
                           'steps to interpret; the rest is not read')
        return []
    if isinstance(value, LaunchDescription):
        return value.entities
    if isinstance(value, UnknownValue):
        interp.loader.note(f'{interp.path}: generate_launch_description() '
                           f'does not give a known launch description '
                           f'({value.reason})')
    else:
        interp.loader.note(f'{interp.path}: generate_launch_description() '
                           'does not return a LaunchDescription')
    return []


def _read_module(interp, tree):
    """Imports, definitions and constants of the module; nothing else runs."""
    for stmt in tree.body:
        if isinstance(stmt, (ast.Import, ast.ImportFrom)):
            interp.import_(stmt, interp.globals)
        elif isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef)):
            interp.define(stmt, interp.globals, [interp.globals])
        elif isinstance(stmt, (ast.Assign, ast.AnnAssign)):
            interp.frames.append(Frame(interp.globals, [], 0))
            try:
                interp.statement(stmt, interp.globals)
            finally:
                interp.frames.pop()
        elif isinstance(stmt, ast.Expr) and isinstance(
                stmt.value, ast.Constant):
            continue  # a docstring
        elif isinstance(stmt, ast.If) and _is_main_guard(stmt.test):
            continue  # never runs under launch
        elif isinstance(stmt, ast.Try):
            for inner in stmt.body:
                if isinstance(inner, (ast.Import, ast.ImportFrom)):
                    interp.import_(inner, interp.globals)
                else:
                    interp.note(inner, 'module-level statement in try: '
                                'not interpreted')
        else:
            interp.note(stmt, f'module-level {type(stmt).__name__} '
                        'statement not interpreted')


def _is_main_guard(test):
    return isinstance(test, ast.Compare) and isinstance(
        test.left, ast.Name) and test.left.id == '__name__'
