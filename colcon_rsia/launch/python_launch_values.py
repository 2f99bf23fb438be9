# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""The values and limits of the Python launch file interpreter.

Shared by the parts of the interpreter
(:mod:`colcon_rsia.launch.python_launch_interpreter` and the modules of its
statements, expressions and calls) and the launch API it knows
(:mod:`colcon_rsia.launch.python_launch_api`). Every limit of the
interpreter is here.
"""

import ast
from dataclasses import dataclass
import re


# AST nodes evaluated for one file: a launch file takes a few thousand;
# loops and calls must not make the analysis run away
MAX_STEPS = 200000
# ... and for all the Python launch files of one load: ten files at their
# limit, so that many files cannot multiply the time of one load
MAX_TOTAL_STEPS = 2000000
# iterations of one interpreted loop (and elements of a range()): launch
# files loop over robots, cameras or arguments, tens of them
MAX_LOOP = 1000
# nested calls of module functions: helpers call each other a few levels
# deep; recursion ends here, each level being many Python frames
MAX_CALL_DEPTH = 16
# nesting of interpreted statements, expressions and calls together; the
# Python stack (a few frames per level) stays well below its limit
# (elements and YAML: common.MAX_NESTING)
MAX_CODE_NESTING = 100
# elements of a list or characters of a string the interpreter builds:
# a value doubled in a loop must not exhaust memory (as
# substitutions.MAX_VALUE_LENGTH for substitutions)
MAX_SIZE = 100000
# bits of an integer the interpreter builds: far beyond any count or port
# in a launch file, small enough that arithmetic and str() stay instant
MAX_INT_BITS = 4000
# exponent of a power of values other than two numbers (numbers go through
# safe_eval's arithmetic and its limits); nothing a launch file writes
MAX_POWER = 64

MISSING = object()
SCALARS = (str, int, float, bool, type(None))
# modules whose classes and functions are recognised by their last name
LAUNCH_MODULES = ('launch', 'launch_ros', 'launch_xml', 'launch_yaml',
                  'ament_index_python')


class BudgetExceeded(Exception):
    """The steps of one file or of one load are used up."""


class ReturnSignal(Exception):
    """A `return` of an interpreted function, with its value."""

    def __init__(self, value):  # noqa: D107
        super().__init__()
        self.value = value


class BreakSignal(Exception):
    """A `break` of an interpreted loop."""


class ContinueSignal(Exception):
    """A `continue` of an interpreted loop."""


@dataclass
class Ref:
    """A module or a name imported from one."""

    qualname: str


@dataclass
class Function:
    """A function defined in the launch file (or a lambda)."""

    node: object
    defaults: list
    kw_defaults: dict
    closure: list  # the environments it was defined in (innermost first)
    name: str


@dataclass
class Bound:
    """A method of a value, such as ``nodes.append`` or ``ld.add_action``."""

    obj: object
    name: str


@dataclass
class LaunchDescription:
    """A `LaunchDescription` built by the file."""

    entities: list


@dataclass
class LaunchSource:
    """A launch description source (the file an include reads)."""

    path: object


@dataclass
class EventHandler:
    """An event handler: its actions run when the event happens."""

    actions: list
    what: str


@dataclass
class Frame:
    """A call of an interpreted function under way."""

    env: dict
    conditional_returns: list
    base: int  # unknown branches entered before the call


class BranchEnd(Exception):
    """A return inside a branch whose condition is not known."""


class HashableValue:
    """A dictionary key that is not a plain scalar (a substitution)."""

    def __init__(self, value):  # noqa: D107
        self.value = value


def is_hashable(value):
    """Whether a value can be a dictionary key of the interpreter as is."""
    return isinstance(value, (str, int, float, bool, type(None)))


def same_value(a, b):
    """Whether two values are the same (one object, or equal scalars)."""
    if a is b:
        return True
    if isinstance(a, SCALARS) and isinstance(b, SCALARS):
        return type(a) is type(b) and a == b
    return False


def safe_format_spec(spec):
    """A format spec without nested fields or huge widths."""
    if '{' in spec or '}' in spec:
        return False
    return all(len(digits) <= 4 for digits in re.findall(r'\d+', spec))


def source_text(node):
    """The source of an AST node, for a note."""
    try:
        return ast.unparse(node)
    except Exception:  # ast.unparse of a synthetic node
        return type(node).__name__
